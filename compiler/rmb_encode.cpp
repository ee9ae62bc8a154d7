// Encoder of the .rmb format (docs/binary-format.md). Each section is written into its own
// buffer; the section table, whose varint offsets depend on its own length, is then sized by
// iterating to a fixed point, and the CRC-32 of everything closes the file.
#include <utility>

#include "compiler/rmb_codec.h"
#include "compiler/rmb_verify.h"

namespace ramus {

namespace {

using rmb::Writer;

void check(bool ok, const char* what) {
  if (!ok) throw RmbError(0, std::string("cannot encode: ") + what);
}

void write_meta(Writer& w, const ir::Grammar& g) {
  w.str(g.name);
  w.u8(std::uint8_t(g.selection));
  const ir::Settings& s = g.settings;
  w.svarint(s.derive);
  w.varint(s.seed);
  for (double v : {s.angle, s.step, s.width, s.width_decay, s.tropism[0], s.tropism[1],
                   s.tropism[2], s.elasticity}) {
    w.f64(v);
  }
  w.svarint(s.max_depth);
}

void write_symbols(Writer& w, const ir::Grammar& g) {
  check(g.symbols.size() >= ir::kTurtleSymbolCount, "fewer symbols than the turtle's");
  w.varint(g.symbols.size() - ir::kTurtleSymbolCount);
  for (int i = 0; i < ir::kTurtleSymbolCount; ++i) w.svarint(g.symbols[i].arity);
  for (std::size_t i = ir::kTurtleSymbolCount; i < g.symbols.size(); ++i) {
    w.str(g.symbols[i].name);
    w.svarint(g.symbols[i].arity);
  }
}

void write_constants(Writer& w, const ir::Grammar& g) {
  w.varint(g.constants.size());
  for (const ir::Constant& c : g.constants) {
    w.str(c.name);
    w.f64(c.value);
    w.u8(c.is_param ? 1 : 0);
  }
}

// Front coding: each location shares most of its "file:line:" with the one before.
void write_locations(Writer& w, const ir::Grammar& g) {
  w.varint(g.locations.size());
  std::string_view prev;
  for (const std::string& s : g.locations) {
    std::size_t common = 0;
    while (common < prev.size() && common < s.size() && prev[common] == s[common]) ++common;
    w.varint(common);
    w.str(std::string_view(s).substr(common));
    prev = s;
  }
}

void write_bytecode(Writer& w, const ir::Grammar& g) {
  w.varint(g.consts.size());
  for (double v : g.consts) w.f64(v);
  w.varint(g.code.size());
  for (const ir::Instr& in : g.code) {
    w.u8(std::uint8_t(in.op));
    if (rmb_has_operand(in.op)) w.varint(in.a);
  }
}

void write_codes(Writer& w, const ir::Grammar& g) {
  w.varint(g.codes.size());
  std::uint32_t prev_end = 0;
  for (const ir::Code& c : g.codes) {
    check(c.begin <= c.end, "a code range that ends before it begins");
    w.svarint(std::int64_t(c.begin) - std::int64_t(prev_end));  // delta: usually 0
    w.varint(c.end - c.begin);
    prev_end = c.end;
    w.varint(c.max_stack);
    w.u8(std::uint8_t(std::uint8_t(c.shape) | (c.random ? 4 : 0)));
    using Shape = ir::Code::Shape;
    if (c.shape == Shape::Constant || c.shape == Shape::ParamOpConst) w.f64(c.value);
    if (c.shape == Shape::Param || c.shape == Shape::ParamOpConst) w.varint(c.slot);
    if (c.shape == Shape::ParamOpConst) w.u8(std::uint8_t(c.op));
    w.varint(c.where);
  }
}

void write_pattern(Writer& w, const ir::Pattern& p) {
  w.varint(p.symbol);
  w.varint(p.any_params ? 0 : std::uint64_t(p.nparams) + 1);
  if (!p.any_params) w.varint(p.first_slot);
}

void write_patterns(Writer& w, const std::vector<ir::Pattern>& ps) {
  w.varint(ps.size());
  for (const ir::Pattern& p : ps) write_pattern(w, p);
}

void write_modules(Writer& w, const ir::Grammar& g, std::uint32_t b, std::uint32_t e,
                   const std::vector<ir::SuccModule>& mods) {
  check(b <= e && e <= mods.size(), "a module range outside its array");
  w.varint(e - b);
  for (std::uint32_t i = b; i < e; ++i) {
    const ir::SuccModule& m = mods[i];
    check(std::size_t(m.arg_begin) + m.nargs <= g.args.size(), "arguments outside the args array");
    w.varint(m.symbol);
    w.varint(m.nargs);
    for (std::uint32_t k = 0; k < m.nargs; ++k) w.varint(g.args[m.arg_begin + k]);
  }
}

std::uint64_t optional_code(ir::CodeId c) { return c == ir::kNoCode ? 0 : std::uint64_t(c) + 1; }

void write_productions(Writer& w, const ir::Grammar& g) {
  w.varint(g.productions.size());
  for (const ir::Production& p : g.productions) {
    w.u8(std::uint8_t(p.kind));
    write_pattern(w, p.predecessor);
    write_patterns(w, p.left);
    write_patterns(w, p.right);
    w.varint(optional_code(p.guard));
    w.varint(p.nslots);
    w.varint(p.where);
    w.str(p.text);
    check(p.alt_begin <= p.alt_end && p.alt_end <= g.alternatives.size(),
          "an alternative range outside its array");
    w.varint(p.alt_end - p.alt_begin);
    for (std::uint32_t a = p.alt_begin; a < p.alt_end; ++a) {
      const ir::Alternative& alt = g.alternatives[a];
      w.varint(optional_code(alt.probability));
      write_modules(w, g, alt.succ_begin, alt.succ_end, g.successors);
    }
  }
}

void write_ignored(Writer& w, const ir::Grammar& g) {
  std::vector<std::uint32_t> ids;
  for (std::size_t s = 0; s < g.ignored.size(); ++s) {
    if (g.ignored[s]) ids.push_back(std::uint32_t(s));
  }
  w.varint(ids.size());
  std::uint32_t prev = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) {  // ascending ids, delta-coded
    w.varint(i == 0 ? ids[i] : ids[i] - prev - 1);
    prev = ids[i];
  }
}

std::size_t varint_size(std::uint64_t v) {
  std::size_t n = 1;
  while (v >= 0x80) {
    v >>= 7;
    ++n;
  }
  return n;
}

}  // namespace

std::string encode_rmb(const ir::Grammar& g) {
  std::vector<std::pair<RmbSection, std::string>> sections;
  auto add = [&](RmbSection id, void (*fill)(Writer&, const ir::Grammar&)) {
    Writer w;
    fill(w, g);
    sections.emplace_back(id, std::move(w.data()));
  };
  add(RmbSection::Meta, write_meta);
  add(RmbSection::Symbols, write_symbols);
  add(RmbSection::Constants, write_constants);
  add(RmbSection::Locations, write_locations);
  add(RmbSection::Bytecode, write_bytecode);
  add(RmbSection::Codes, write_codes);
  add(RmbSection::Productions, write_productions);
  add(RmbSection::Axiom, [](Writer& w, const ir::Grammar& gr) {
    write_modules(w, gr, 0, std::uint32_t(gr.axiom.size()), gr.axiom);
  });
  add(RmbSection::Ignored, write_ignored);

  // Header: magic, version, flags, then the table. The table's size depends on the offsets it
  // holds, which depend on its size: grow the guess until it stops changing.
  constexpr std::size_t kFixed = 8;
  std::size_t table = 0;
  for (;;) {
    std::size_t size = varint_size(sections.size());
    std::size_t at = kFixed + table;
    for (const auto& [id, body] : sections) {
      size += varint_size(std::uint64_t(id)) + varint_size(at) + varint_size(body.size());
      at += body.size();
    }
    if (size == table) break;
    table = size;
  }
  Writer w;
  w.bytes(std::string_view("RMB\x1a", 4));
  w.u16(kRmbVersion);
  w.u16(0);  // flags: no quantization, no compression
  w.varint(sections.size());
  std::size_t at = kFixed + table;
  for (const auto& [id, body] : sections) {
    w.varint(std::uint64_t(id));
    w.varint(at);
    w.varint(body.size());
    at += body.size();
  }
  for (const auto& [id, body] : sections) w.bytes(body);
  w.u32(rmb::crc32(w.data()));
  return std::move(w.data());
}

}  // namespace ramus
