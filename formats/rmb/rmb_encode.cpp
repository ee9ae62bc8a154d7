// Encoder of the .rmb format (docs/binary-format.md). Each section is written into its own
// buffer; the section table, whose varint offsets depend on its own length, is then sized by
// iterating to a fixed point, and the CRC-32 of everything closes the file.
#include <algorithm>
#include <bit>
#include <cmath>
#include <unordered_map>
#include <utility>

#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_verify.h"
#include "formats/rmb/rmb_zstd.h"

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
    w.real(v);
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
    w.real(c.value);
    w.u8(c.is_param ? 1 : 0);
  }
}

// Front coding: each location shares most of its "file:line:" with the one before.
// A stripped file (flag bit 2) leaves out every location index and production text.
void write_locations(Writer& w, const ir::Grammar& g, bool stripped) {
  if (stripped) {  // the section stays, empty: the layout of every file is the same
    w.varint(0);
    return;
  }
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

// Version 2 (docs/binary-format.md, section 5): each pool entry is a new value or a repeat of
// an earlier one; a const operand is the pool index relative to the one after the previous
// const's, a jump's relative to the next instruction -- both usually 0.
void write_bytecode(Writer& w, const ir::Grammar& g, int version) {
  if (version == 1) {  // every pool value, every operand absolute
    w.varint(g.consts.size());
    for (double v : g.consts) w.real(v);
    w.varint(g.code.size());
    for (const ir::Instr& in : g.code) {
      w.u8(std::uint8_t(in.op));
      if (rmb_has_operand(in.op)) w.varint(in.a);
    }
    return;
  }
  w.varint(g.consts.size());
  // By the bits of the value as stored (-0 and NaN payloads kept; in a quantized file two
  // values of one quantum are one), so that re-encoding a decoded file gives the same bytes.
  std::unordered_map<std::uint64_t, std::uint64_t> seen;
  for (double v : g.consts) {
    const auto [it, fresh] =
        seen.emplace(std::bit_cast<std::uint64_t>(w.stored_real(v)), seen.size());
    w.varint(it->second);
    if (fresh) w.real(v);
  }
  w.varint(g.code.size());
  std::int64_t next_const = 0;
  for (std::size_t i = 0; i < g.code.size(); ++i) {
    const ir::Instr& in = g.code[i];
    w.u8(std::uint8_t(in.op));
    if (in.op == ir::Op::Const) {
      w.svarint(std::int64_t(in.a) - next_const);
      next_const = std::int64_t(in.a) + 1;
    } else if (in.op == ir::Op::Jump || in.op == ir::Op::JumpIfFalse) {
      w.svarint(std::int64_t(in.a) - std::int64_t(i) - 1);
    } else if (rmb_has_operand(in.op)) {
      w.varint(in.a);
    }
  }
}

// Version 2: a code whose record its instructions imply (rmb_code_is_implied) and that starts
// where the previous one ended is just its length; the others are written out in full.
void write_codes(Writer& w, const ir::Grammar& g, bool stripped, int version) {
  w.varint(g.codes.size());
  std::uint32_t prev_end = 0;
  for (const ir::Code& c : g.codes) {
    check(c.begin <= c.end, "a code range that ends before it begins");
    const bool implied = version >= 2 && c.begin == prev_end && rmb_code_is_implied(g, c);
    if (version == 1) {  // begin delta, then length
      w.svarint(std::int64_t(c.begin) - std::int64_t(prev_end));
      w.varint(c.end - c.begin);
    } else {
      w.varint((std::uint64_t(c.end - c.begin) << 1) | (implied ? 0 : 1));
      if (!implied) w.svarint(std::int64_t(c.begin) - std::int64_t(prev_end));
    }
    if (!implied) {
      w.varint(c.max_stack);
      w.u8(std::uint8_t(std::uint8_t(c.shape) | (c.random ? 4 : 0)));
      using Shape = ir::Code::Shape;
      if (c.shape == Shape::Constant || c.shape == Shape::ParamOpConst) w.real(c.value);
      if (c.shape == Shape::Param || c.shape == Shape::ParamOpConst) w.varint(c.slot);
      if (c.shape == Shape::ParamOpConst) w.u8(std::uint8_t(c.op));
    }
    prev_end = c.end;
    if (!stripped) w.varint(c.where);
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

// Code references (version 2): relative to the code after the one referenced before in the
// same section, so the usual run of fresh codes 274, 275, ... is a run of zeros.
struct CodeRefs {
  bool absolute = false;  // version 1: the id itself (optional ones + 1)
  std::int64_t next = 0;
  void write(Writer& w, ir::CodeId c) {
    if (absolute) {
      w.varint(c);
      return;
    }
    w.svarint(std::int64_t(c) - next);
    next = std::int64_t(c) + 1;
  }
  void write_optional(Writer& w, ir::CodeId c) {  // 0: none; else the delta's zigzag + 1
    if (absolute) {
      w.varint(c == ir::kNoCode ? 0 : std::uint64_t(c) + 1);
      return;
    }
    if (c == ir::kNoCode) {
      w.varint(0);
      return;
    }
    w.varint(rmb::zigzag(std::int64_t(c) - next) + 1);
    next = std::int64_t(c) + 1;
  }
};

void write_modules(Writer& w, const ir::Grammar& g, CodeRefs& refs, std::uint32_t b,
                   std::uint32_t e, const std::vector<ir::SuccModule>& mods) {
  check(b <= e && e <= mods.size(), "a module range outside its array");
  w.varint(e - b);
  for (std::uint32_t i = b; i < e; ++i) {
    const ir::SuccModule& m = mods[i];
    check(std::size_t(m.arg_begin) + m.nargs <= g.args.size(), "arguments outside the args array");
    w.varint(m.symbol);
    w.varint(m.nargs);
    for (std::uint32_t k = 0; k < m.nargs; ++k) refs.write(w, g.args[m.arg_begin + k]);
  }
}

void write_productions(Writer& w, const ir::Grammar& g, bool stripped, int version) {
  CodeRefs refs;
  refs.absolute = version == 1;
  w.varint(g.productions.size());
  for (const ir::Production& p : g.productions) {
    w.u8(std::uint8_t(p.kind));
    write_pattern(w, p.predecessor);
    write_patterns(w, p.left);
    write_patterns(w, p.right);
    refs.write_optional(w, p.guard);
    w.varint(p.nslots);
    if (!stripped) {
      w.varint(p.where);
      w.str(p.text);
    }
    if (g.selection ==
        ir::Selection::Nearest) {  // rule-space key and query (docs/binary-format.md)
      check(p.key.size() == p.query.size(), "a rule-space key without its query");
      w.varint(p.key.size());
      for (double k : p.key) w.real(k);
      for (ir::CodeId c : p.query) refs.write(w, c);
    }
    check(p.alt_begin <= p.alt_end && p.alt_end <= g.alternatives.size(),
          "an alternative range outside its array");
    w.varint(p.alt_end - p.alt_begin);
    for (std::uint32_t a = p.alt_begin; a < p.alt_end; ++a) {
      const ir::Alternative& alt = g.alternatives[a];
      refs.write_optional(w, alt.probability);
      write_modules(w, g, refs, alt.succ_begin, alt.succ_end, g.successors);
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

// Section 11 (docs/binary-format.md, voxel rule tables).
void write_voxels(Writer& w, const std::vector<RmbVoxelTable>& tables) {
  w.varint(tables.size());
  for (const RmbVoxelTable& t : tables) {
    check(!t.levels || (*t.levels >= 1 && *t.levels <= 64), "voxel levels outside 1..64");
    check(!t.classes || (*t.classes >= 1 && *t.classes <= 256), "voxel classes outside 1..256");
    w.str(t.name);
    w.u8(std::uint8_t((t.levels ? 1 : 0) | (t.classes ? 2 : 0) | (t.seed ? 4 : 0) |
                      (t.axiom ? 8 : 0)));
    if (t.levels) w.varint(*t.levels);
    if (t.classes) w.varint(*t.classes);
    if (t.seed) w.varint(*t.seed);
    if (t.axiom) w.str(*t.axiom);
    w.varint(t.rules.size());
    for (const wavelet::VoxelRule& r : t.rules) {
      const std::uint32_t limit = t.classes.value_or(256);
      check(r.parent < limit, "a voxel class outside the block's classes");
      w.u8(r.parent);
      for (std::uint8_t c : r.children) {
        check(c < limit, "a voxel class outside the block's classes");
        w.u8(c);
      }
      w.varint(r.count);
    }
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

int rmb_quantum_exponent(double tolerance) {
  if (!(tolerance > 0) || !std::isfinite(tolerance)) {
    throw RmbError(0, "cannot encode: expected a tolerance that is a positive number");
  }
  const int e = int(std::floor(std::log2(2 * tolerance)));
  return std::clamp(e, rmb::kMinQuantumExponent, rmb::kMaxQuantumExponent);
}

std::string encode_rmb(const ir::Grammar& g, const RmbEncodeOptions& options) {
  return encode_rmb(g, {}, options);
}

std::string encode_rmb(const ir::Grammar& g, const std::vector<RmbVoxelTable>& voxels,
                       const RmbEncodeOptions& options) {
  return encode_rmb(g, voxels, RmbPieces{}, options);
}

std::string encode_rmb(const ir::Grammar& g, const std::vector<RmbVoxelTable>& voxels,
                       const RmbPieces& pieces, const RmbEncodeOptions& options) {
  return encode_rmb(g, voxels, pieces, RmbPieceStream{}, options);
}

std::string encode_rmb(const ir::Grammar& g, const std::vector<RmbVoxelTable>& voxels,
                       const RmbPieces& pieces, const RmbPieceStream& placed,
                       const RmbEncodeOptions& options) {
  std::optional<int> exponent;
  if (options.tolerance) exponent = rmb_quantum_exponent(*options.tolerance);
  std::vector<std::pair<RmbSection, std::string>> sections;
  const bool strip = options.strip;
  const int version = options.version;
  if (version < kRmbOldestVersion || version > kRmbVersion) {
    throw RmbError(0, "cannot encode: format version " + std::to_string(version) +
                          " (this encoder writes 1 and 2)");
  }
  auto add = [&](RmbSection id, auto fill) {
    Writer w;
    if (version >= 2) w.decimal();  // reals as decimals (and, when quantized, the shorter form)
    if (exponent) {
      if (id == RmbSection::Meta) w.svarint(*exponent);  // the quantum, before everything else
      w.quantize(*exponent);
    }
    fill(w, g);
    sections.emplace_back(id, std::move(w.data()));
  };
  add(RmbSection::Meta, write_meta);
  add(RmbSection::Symbols, write_symbols);
  add(RmbSection::Constants, write_constants);
  add(RmbSection::Locations,
      [strip](Writer& w, const ir::Grammar& gr) { write_locations(w, gr, strip); });
  add(RmbSection::Bytecode,
      [version](Writer& w, const ir::Grammar& gr) { write_bytecode(w, gr, version); });
  add(RmbSection::Codes,
      [strip, version](Writer& w, const ir::Grammar& gr) { write_codes(w, gr, strip, version); });
  add(RmbSection::Productions, [strip, version](Writer& w, const ir::Grammar& gr) {
    write_productions(w, gr, strip, version);
  });
  add(RmbSection::Axiom, [version](Writer& w, const ir::Grammar& gr) {
    CodeRefs refs;
    refs.absolute = version == 1;
    write_modules(w, gr, refs, 0, std::uint32_t(gr.axiom.size()), gr.axiom);
  });
  add(RmbSection::Ignored, write_ignored);
  if (!pieces.empty()) {
    add(RmbSection::Pieces,
        [&pieces](Writer& w, const ir::Grammar&) { write_rmb_pieces(w, pieces); });
  }
  if (!voxels.empty()) {
    add(RmbSection::VoxelRules,
        [&voxels](Writer& w, const ir::Grammar&) { write_voxels(w, voxels); });
  }
  if (!placed.empty()) {
    // Exact bytes whatever the options: quantized reals (--tolerance) do not apply, the poses
    // are quantized by the stream's own rule.
    Writer w;
    write_rmb_piece_stream(w, placed);
    sections.emplace_back(RmbSection::PieceStream, std::move(w.data()));
  }

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
  w.u16(std::uint16_t(version));
  const std::uint16_t flags =
      std::uint16_t((exponent ? kRmbQuantized : 0) | (options.strip ? kRmbStripped : 0));
  w.u16(flags);
  w.varint(sections.size());
  std::size_t at = kFixed + table;
  for (const auto& [id, body] : sections) {
    w.varint(std::uint64_t(id));
    w.varint(at);
    w.varint(body.size());
    at += body.size();
  }
  for (const auto& [id, body] : sections) w.bytes(body);
  if (options.zstd) {  // flag bit 1: the table and the sections as one zstd frame
    const std::string frame = rmb_zstd_compress(std::string_view(w.data()).substr(kFixed));
    Writer z;
    z.bytes(std::string_view(w.data()).substr(0, 6));
    z.u16(flags | kRmbZstd);
    z.bytes(frame);
    z.u32(rmb::crc32(z.data()));
    return std::move(z.data());
  }
  w.u32(rmb::crc32(w.data()));
  return std::move(w.data());
}

}  // namespace ramus
