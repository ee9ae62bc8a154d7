// Decoder of the .rmb format (docs/binary-format.md). Reads the header and checks the CRC-32
// before anything else, then the sections in their fixed order, each through a Reader bounded
// to the section, checking every id and range as it is read; expressions are verified last
// (formats/rmb/rmb_verify.cpp) once every array they point into is known.
#include <set>

#include "core/number_text.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_verify.h"
#include "formats/rmb/rmb_zstd.h"

namespace ramus {

namespace {

using rmb::Reader;

constexpr std::size_t kMaxFile = std::size_t(64) << 20;
constexpr std::size_t kMaxString = std::size_t(1) << 20;
constexpr std::size_t kMaxLocation = 4096;
constexpr std::size_t kHeader = 8, kTrailer = 4;
constexpr std::size_t kSectionCount = 9;  // Meta .. Ignored, all required

struct Decoder {
  std::string_view bytes;
  std::vector<rmb::TraceEntry>* trace;
  ir::Grammar g;                     // starts with the 16 turtle symbols
  std::vector<std::size_t> code_at;  // byte offset of each code record, for error messages

  bool quantized = false;  // flag bit 0: reals are multiples of 2^exponent
  int exponent = 0;
  bool stripped = false;  // flag bit 2: no location indices, no production texts
  int version = kRmbVersion;
  std::vector<RmbVoxelTable> voxels;
  RmbPieces pieces;
  RmbPieceStream placed;

  Reader section(std::size_t b, std::size_t e) {
    Reader r(bytes, b, e, trace);
    if (quantized && exponent_known) r.quantize(exponent);
    if (version >= 2) r.decimal();  // version 2 reals (formats/rmb/rmb_io.h)
    return r;
  }
  bool exponent_known = false;

  void meta(Reader& r) {
    if (quantized) {  // the quantum 2^e of every real in the file, first in the meta section
      const std::size_t at = r.pos();
      const std::int64_t e = r.svarint("quantum exponent");
      if (e < rmb::kMinQuantumExponent || e > rmb::kMaxQuantumExponent) {
        r.fail_at(at, "expected a quantum exponent in -60..20");
      }
      exponent = int(e);
      exponent_known = true;
      r.quantize(exponent);
    }
    g.name = r.str("name", kMaxString);
    const std::uint8_t sel = r.u8("selection");
    if (sel > std::uint8_t(ir::Selection::Nearest)) r.fail("expected selection 0 or 1");
    g.selection = ir::Selection(sel);
    ir::Settings& s = g.settings;
    const std::int64_t derive = r.svarint("derive");
    if (derive < 0 || derive > 1'000'000) r.fail("expected derive in 0..1000000");
    s.derive = int(derive);
    s.seed = r.varint("seed");
    s.angle = r.real("angle");
    s.step = r.real("step");
    s.width = r.real("width");
    s.width_decay = r.real("width_decay");
    s.tropism[0] = r.real("tropism.x");
    s.tropism[1] = r.real("tropism.y");
    s.tropism[2] = r.real("tropism.z");
    s.elasticity = r.real("elasticity");
    const std::int64_t depth = r.svarint("max_depth");
    if (depth < 0 || depth > 255) r.fail("expected max_depth in 0..255");
    s.max_depth = int(depth);
  }

  std::int16_t arity(Reader& r, const char* field = "arity") {
    const std::size_t at = r.pos();
    const std::int64_t a = r.svarint(field);
    if (a < -1 || a > 32767) r.fail_at(at, "expected an arity in -1..32767");
    return std::int16_t(a);
  }

  void symbols(Reader& r) {
    const std::size_t extra = r.count("extra symbols", 65536 - ir::kTurtleSymbolCount, 2);
    static const char* kFields[ir::kTurtleSymbolCount] = {
        "arity of F",  "arity of f", "arity of +", "arity of -", "arity of &", "arity of ^",
        "arity of \\", "arity of /", "arity of |", "arity of $", "arity of [", "arity of ]",
        "arity of !",  "arity of '", "arity of ~", "arity of %"};
    for (int i = 0; i < ir::kTurtleSymbolCount; ++i) g.symbols[i].arity = arity(r, kFields[i]);
    std::set<std::string> seen(std::begin(ir::kTurtleNames), std::end(ir::kTurtleNames));
    for (std::size_t i = 0; i < extra; ++i) {
      r.heading("symbol " + std::to_string(ir::kTurtleSymbolCount + i));
      const std::size_t at = r.pos();
      ir::Symbol s;
      s.name = r.str("name", 4096);
      if (s.name.empty() || !seen.insert(s.name).second) {
        r.fail_at(at, "expected a new, non-empty symbol name, found \"" + s.name + "\"");
      }
      s.arity = arity(r);
      s.turtle = ir::polygon_op(s.name);  // the polygon symbols are stored by name
      g.symbols.push_back(std::move(s));
      g.ignored.push_back(0);
    }
  }

  void constants(Reader& r) {
    const std::size_t n = r.count("constants", kMaxFile, quantized || version >= 2 ? 3 : 10);
    for (std::size_t i = 0; i < n; ++i) {
      r.heading("constant " + std::to_string(i));
      ir::Constant c;
      c.name = r.str("name", 4096);
      c.value = r.real("value");
      const std::uint8_t p = r.u8("is_param");
      if (p > 1) r.fail("expected is_param 0 or 1");
      c.is_param = p == 1;
      g.constants.push_back(std::move(c));
    }
  }

  void locations(Reader& r) {
    const std::size_t n = r.count("locations", stripped ? 0 : kMaxFile, 2);
    g.locations.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {  // front-coded: a prefix of the previous, then a suffix
      const std::size_t keep = r.bounded("shared prefix", i == 0 ? 0 : g.locations.back().size());
      std::string s = i == 0 ? std::string() : g.locations.back().substr(0, keep);
      s += r.str("suffix", kMaxLocation);
      // Front coding could otherwise grow every entry by a byte: quadratic memory from a file.
      if (s.size() > kMaxLocation) r.fail("expected a location of at most 4096 bytes");
      g.locations.push_back(std::move(s));
    }
  }

  void bytecode(Reader& r) {
    if (version == 1) {
      const std::size_t nc = r.count("constant pool size", kMaxFile, quantized ? 1 : 8);
      g.consts.reserve(nc);
      for (std::size_t i = 0; i < nc; ++i) g.consts.push_back(r.real("const"));
    } else {  // each entry: a repeat of an earlier value, or a new one
      const std::size_t nc = r.count("constant pool size", kMaxFile);
      g.consts.reserve(nc);
      std::vector<double> values;
      for (std::size_t i = 0; i < nc; ++i) {
        const std::uint64_t k = r.bounded("value index", values.size());
        if (k == values.size()) {
          r.explain("new");
          values.push_back(r.real("const"));
        } else {
          r.explain(shortest_text(values[k]));
        }
        g.consts.push_back(values[k]);
      }
    }
    const std::size_t ni = r.count("instructions", kMaxFile);
    g.code.reserve(ni);
    std::int64_t next_const = 0;
    for (std::size_t i = 0; i < ni; ++i) {
      const std::uint8_t op = r.u8("op");
      if (op > std::uint8_t(ir::Op::Call)) r.fail_at(r.pos() - 1, "expected an opcode <= 20");
      ir::Instr in{ir::Op(op), 0};
      if (version >= 2 &&
          (in.op == ir::Op::Const || in.op == ir::Op::Jump || in.op == ir::Op::JumpIfFalse)) {
        // Relative: to the pool entry after the previous const's, to the next instruction.
        const std::size_t at = r.pos();
        const std::int64_t base = in.op == ir::Op::Const ? next_const : std::int64_t(i) + 1;
        const std::int64_t d =
            r.svarint(in.op == ir::Op::Const ? "pool index delta" : "jump delta");
        if (d < -base || d > std::int64_t(0xFFFFFFFEu) - base) {
          r.fail_at(at, "expected an operand in 0..4294967294");
        }
        in.a = std::uint32_t(base + d);
        if (in.op == ir::Op::Const) next_const = std::int64_t(in.a) + 1;
      } else if (rmb_has_operand(in.op)) {
        in.a = std::uint32_t(r.bounded("operand", 0xFFFFFFFEu));
      }
      g.code.push_back(in);
    }
  }

  std::uint32_t location(Reader& r) {
    return std::uint32_t(r.bounded("where", g.locations.empty() ? 0 : g.locations.size() - 1));
  }

  void codes(Reader& r) {
    // Version 2: varint length << 1 | explicit, the rest only when explicit (else implied by
    // the instructions, rmb_implied_code); version 1: every record in full.
    const std::size_t n = r.count("codes", kMaxFile, version == 1 ? (stripped ? 4 : 5) : 1);
    std::int64_t prev_end = 0;
    for (std::size_t i = 0; i < n; ++i) {
      r.heading("code " + std::to_string(i));
      code_at.push_back(r.pos());
      ir::Code c;
      bool full = true;
      std::uint64_t len = 0;
      if (version >= 2) {
        const std::uint64_t v = r.varint("length << 1 | explicit");
        len = v >> 1;
        full = v & 1;
      }
      const std::int64_t begin = full ? prev_end + r.svarint("begin delta") : prev_end;
      if (version == 1) len = r.varint("length");
      if (begin < 0 || std::uint64_t(begin) > g.code.size() ||
          len > std::uint64_t(g.code.size()) - std::uint64_t(begin)) {
        r.fail_at(code_at.back(), "expected a code range inside the " +
                                      std::to_string(g.code.size()) + " instructions");
      }
      c.begin = std::uint32_t(begin);
      c.end = std::uint32_t(begin + std::int64_t(len));
      prev_end = c.end;
      if (full) {
        c.max_stack = std::uint16_t(r.bounded("max_stack", kRmbMaxStack));
        const std::uint8_t flags = r.u8("shape | random << 2");
        if (flags > 7) r.fail_at(r.pos() - 1, "expected shape flags <= 7");
        c.shape = ir::Code::Shape(flags & 3);
        c.random = flags & 4;
        using Shape = ir::Code::Shape;
        if (c.shape == Shape::Constant || c.shape == Shape::ParamOpConst) c.value = r.real("value");
        if (c.shape == Shape::Param || c.shape == Shape::ParamOpConst) {
          c.slot = std::uint32_t(r.bounded("slot", ir::kMaxSlots - 1));
        }
        if (c.shape == Shape::ParamOpConst) {
          const std::uint8_t op = r.u8("op");
          if (op < std::uint8_t(ir::Op::Add) || op > std::uint8_t(ir::Op::Div)) {
            r.fail_at(r.pos() - 1, "expected op add, sub, mul or div");
          }
          c.op = ir::Op(op);
        }
      } else {
        const ir::Code implied = rmb_implied_code(g, c.begin, c.end);
        if (implied.max_stack > kRmbMaxStack) {
          r.fail_at(code_at.back(),
                    "expected an expression whose stack can be followed and is "
                    "at most 256 deep");
        }
        c.max_stack = implied.max_stack;
        c.shape = implied.shape;
        c.random = implied.random;
        c.value = implied.value;
        c.slot = implied.slot;
        c.op = implied.op;
      }
      if (!stripped) c.where = location(r);
      g.codes.push_back(c);
    }
  }

  // Code references: version 1 absolute; version 2 relative to next_code, the code after the
  // one referenced before in the same section (reset per section).
  std::int64_t next_code = 0;
  ir::CodeId code_id(Reader& r, const char* field) {
    if (g.codes.empty()) r.fail("expected a code id, but the grammar has no codes");
    if (version == 1) return ir::CodeId(r.bounded(field, g.codes.size() - 1));
    const std::size_t at = r.pos();
    return relative_code(r, at, next_code + r.svarint(field));
  }
  ir::CodeId optional_code(Reader& r, const char* field) {
    if (version == 1) {
      const std::uint64_t v = r.bounded(field, g.codes.size());
      return v == 0 ? ir::kNoCode : ir::CodeId(v - 1);
    }
    const std::size_t at = r.pos();
    const std::uint64_t v = r.varint(field);
    if (v == 0) return ir::kNoCode;
    return relative_code(r, at, next_code + rmb::unzigzag(v - 1));
  }
  // A version-2 code id c read at `at`: checked, and the base of the next relative one.
  ir::CodeId relative_code(Reader& r, std::size_t at, std::int64_t c) {
    if (c < 0 || c >= std::int64_t(g.codes.size())) {
      r.fail_at(at, "expected a code id below " + std::to_string(g.codes.size()) + ", found " +
                        std::to_string(c));
    }
    r.explain("code " + std::to_string(c));
    next_code = c + 1;
    return ir::CodeId(c);
  }
  ir::SymbolId symbol(Reader& r) { return ir::SymbolId(r.bounded("symbol", g.symbols.size() - 1)); }

  ir::Pattern pattern(Reader& r) {
    ir::Pattern p;
    p.symbol = symbol(r);
    const std::uint64_t np = r.bounded("nparams + 1 (0: any)", ir::kMaxSlots + 1);
    if (np > 0) {
      p.any_params = false;
      p.nparams = std::uint16_t(np - 1);
      p.first_slot = std::uint16_t(r.bounded("first_slot", ir::kMaxSlots - p.nparams));
    }
    return p;
  }

  void patterns(Reader& r, const char* field, std::vector<ir::Pattern>& out) {
    const std::size_t n = r.count(field, 4096, 2);
    for (std::size_t i = 0; i < n; ++i) out.push_back(pattern(r));
  }

  // Modules with their argument codes appended to g.args; returns the parameters written.
  std::uint32_t modules(Reader& r, std::vector<ir::SuccModule>& out, std::uint32_t max_args) {
    const std::size_t n = r.count("modules", kMaxFile, 2);
    std::uint32_t params = 0;
    for (std::size_t i = 0; i < n; ++i) {
      ir::SuccModule m;
      m.symbol = symbol(r);
      m.nargs = std::uint16_t(r.count("nargs", max_args));
      m.arg_begin = std::uint32_t(g.args.size());
      for (std::uint32_t k = 0; k < m.nargs; ++k) g.args.push_back(code_id(r, "arg code"));
      params += m.nargs;
      out.push_back(m);
    }
    return params;
  }

  void productions(Reader& r) {
    next_code = 0;
    const std::size_t n = r.count("productions", kMaxFile, stripped ? 8 : 10);
    for (std::size_t i = 0; i < n; ++i) {
      r.heading("production " + std::to_string(i));
      ir::Production p;
      const std::uint8_t kind = r.u8("kind");
      if (kind > std::uint8_t(ir::Kind::Decompose)) r.fail_at(r.pos() - 1, "expected kind 0..2");
      p.kind = ir::Kind(kind);
      p.predecessor = pattern(r);
      patterns(r, "left context", p.left);
      patterns(r, "right context", p.right);
      p.guard = optional_code(r, version == 1 ? "guard + 1 (0: none)" : "guard (0: none)");
      p.nslots = std::uint16_t(r.bounded("nslots", ir::kMaxSlots));
      if (stripped) {
        p.text = "#" + std::to_string(i);
      } else {
        p.where = location(r);
        p.text = r.str("text", kMaxString);
      }
      if (g.selection == ir::Selection::Nearest) {  // rule-space key and query
        const std::size_t nk = r.count("key coordinates", kMaxFile, 2);
        for (std::size_t k = 0; k < nk; ++k) p.key.push_back(r.real("key"));
        for (std::size_t k = 0; k < nk; ++k) p.query.push_back(code_id(r, "query code"));
      }
      const std::size_t alternatives_at = r.pos();
      const std::size_t na = r.count("alternatives", kMaxFile, 2);
      // Every production the compiler writes has a successor; the derivation chooses among them.
      if (na == 0) r.fail_at(alternatives_at, "expected at least one alternative");
      p.alt_begin = std::uint32_t(g.alternatives.size());
      for (std::size_t a = 0; a < na; ++a) {
        r.heading("alternative " + std::to_string(a));
        ir::Alternative alt;
        alt.production = std::uint32_t(i);
        alt.probability =
            optional_code(r, version == 1 ? "probability + 1 (0: none)" : "probability (0: none)");
        alt.succ_begin = std::uint32_t(g.successors.size());
        alt.out_params = modules(r, g.successors, 65535);
        alt.succ_end = std::uint32_t(g.successors.size());
        g.alternatives.push_back(alt);
      }
      p.alt_end = std::uint32_t(g.alternatives.size());
      g.productions.push_back(std::move(p));
    }
  }

  void axiom(Reader& r) {
    next_code = 0;
    modules(r, g.axiom, ir::kMaxSlots);
  }

  // A stripped file's stand-in locations (rmb_stripped_location): "production i" for each
  // production and every expression it holds first, "axiom" for the rest.
  void name_stripped_locations() {
    const auto n = std::uint32_t(g.productions.size());
    for (std::uint32_t i = 0; i < n; ++i) g.locations.push_back(rmb_stripped_location(i));
    g.locations.emplace_back(kRmbStrippedAxiomLocation);
    std::vector<bool> named(g.codes.size(), false);
    for (ir::Code& c : g.codes) c.where = n;
    auto name = [&](ir::CodeId c, std::uint32_t i) {
      if (c == ir::kNoCode || named[c]) return;
      named[c] = true;
      g.codes[c].where = i;
    };
    for (std::uint32_t i = 0; i < n; ++i) {
      ir::Production& p = g.productions[i];
      p.where = i;
      name(p.guard, i);
      for (ir::CodeId c : p.query) name(c, i);
      for (std::uint32_t a = p.alt_begin; a < p.alt_end; ++a) {
        const ir::Alternative& alt = g.alternatives[a];
        name(alt.probability, i);
        for (std::uint32_t m = alt.succ_begin; m < alt.succ_end; ++m) {
          const ir::SuccModule& mod = g.successors[m];
          for (std::uint32_t k = 0; k < mod.nargs; ++k) name(g.args[mod.arg_begin + k], i);
        }
      }
    }
  }

  void ignored(Reader& r) {
    const std::size_t n = r.count("ignored symbols", g.symbols.size());
    std::uint64_t next = 0;  // the smallest id the next entry may name
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t id = next + r.bounded("id delta", g.symbols.size() - 1 - next);
      g.ignored[id] = 1;
      next = id + 1;
      if (i + 1 < n && next >= g.symbols.size()) r.fail("expected no more ignored symbols");
    }
  }

  // Section 11: the voxel rule tables of `voxels` blocks.
  void voxel_rules(Reader& r) {
    const std::size_t n = r.count("voxel tables", kMaxFile, 3);
    for (std::size_t i = 0; i < n; ++i) {
      r.heading("voxels " + std::to_string(i));
      RmbVoxelTable t;
      const std::size_t name_at = r.pos();
      t.name = r.str("name", 4096);
      if (t.name.empty()) r.fail_at(name_at, "expected a non-empty voxels block name");
      const std::uint8_t present = r.u8("settings present");
      if (present > 15) r.fail_at(r.pos() - 1, "expected settings bits <= 15");
      if (present & 1) {
        const std::size_t at = r.pos();
        const std::uint64_t v = r.varint("levels");
        if (v < 1 || v > 64) r.fail_at(at, "expected levels in 1..64");
        t.levels = std::uint32_t(v);
      }
      if (present & 2) {
        const std::size_t at = r.pos();
        const std::uint64_t v = r.varint("classes");
        if (v < 1 || v > 256) r.fail_at(at, "expected classes in 1..256");
        t.classes = std::uint32_t(v);
      }
      if (present & 4) t.seed = r.bounded("seed", std::uint64_t(1) << 53);  // a .ramus number
      if (present & 8) t.axiom = r.str("axiom", 4096);
      const std::uint32_t limit = t.classes.value_or(256);
      const std::size_t rules = r.count("rules", kMaxFile, 10);  // 9 class bytes and a weight
      t.rules.reserve(rules);
      for (std::size_t k = 0; k < rules; ++k) {
        r.heading("rule " + std::to_string(k));
        wavelet::VoxelRule rule;
        auto cls = [&](const char* field) {
          const std::uint8_t c = r.u8(field);
          if (c >= limit) {
            r.fail_at(r.pos() - 1, "expected a class below " + std::to_string(limit) + ", found " +
                                       std::to_string(c));
          }
          return c;
        };
        rule.parent = cls("parent");
        for (std::uint8_t& c : rule.children) c = cls("child");
        rule.count = std::uint32_t(r.bounded("weight (0: none)", 0xFFFFFFFFu));
        t.rules.push_back(rule);
      }
      voxels.push_back(std::move(t));
    }
  }

  void run_section(RmbSection id, Reader& r) {
    switch (id) {
      case RmbSection::Meta:
        return meta(r);
      case RmbSection::Symbols:
        return symbols(r);
      case RmbSection::Constants:
        return constants(r);
      case RmbSection::Locations:
        return locations(r);
      case RmbSection::Bytecode:
        return bytecode(r);
      case RmbSection::Codes:
        return codes(r);
      case RmbSection::Productions:
        return productions(r);
      case RmbSection::Axiom:
        return axiom(r);
      case RmbSection::Ignored:
        return ignored(r);
      case RmbSection::Pieces:
        pieces = read_rmb_pieces(r);
        return;
      case RmbSection::VoxelRules:
        return voxel_rules(r);
      case RmbSection::PieceStream:
        placed = read_rmb_piece_stream(r);
        return;
      default:
        r.fail("expected a known section");
    }
  }
};

const char* section_name(std::size_t id) {
  static const char* kNames[] = {
      "?",           "meta",  "symbols", "constants",  "locations",         "bytecode",     "codes",
      "productions", "axiom", "ignored", "piece sets", "voxel rule tables", "placed pieces"};
  return id < std::size(kNames) ? kNames[id] : "reserved";
}

std::uint16_t check_header(Reader& r, std::string_view bytes, const RmbDecodeOptions& options) {
  if (bytes.size() > kMaxFile) r.fail("expected a file of at most 64 MiB");
  if (r.raw("magic", 4) != std::string_view("RMB\x1a", 4))
    r.fail_at(0, "expected magic \"RMB\\x1a\"");
  const std::uint16_t version = r.u16("version");
  if (version < kRmbOldestVersion || version > kRmbVersion)
    r.fail_at(4, "expected format version 1 or 2, found " + std::to_string(version));
  const std::uint16_t flags = r.u16("flags");
  if (flags & ~kRmbKnownFlags) {
    r.fail_at(6, "expected flags with only bits 0 (quantized), 1 (zstd) and 2 (stripped), found " +
                     std::to_string(flags));
  }
  if (bytes.size() < kHeader + kTrailer) r.fail_at(bytes.size(), "expected at least 12 bytes");
  Reader tail(bytes, bytes.size() - kTrailer, bytes.size(), nullptr);
  const std::uint32_t stored = tail.u32("crc32");
  const std::uint32_t actual = rmb::crc32(bytes.substr(0, bytes.size() - kTrailer));
  if (options.verify_checksum && stored != actual) {
    r.fail_at(bytes.size() - kTrailer, "expected CRC-32 " + std::to_string(actual) + ", found " +
                                           std::to_string(stored) + " (the file is corrupted)");
  }
  return flags;
}

}  // namespace

std::string rmb_uncompressed(std::string_view bytes, const RmbDecodeOptions& options) {
  const std::size_t body_end = bytes.size() >= kTrailer ? bytes.size() - kTrailer : 0;
  Reader r(bytes, 0, body_end, nullptr);
  const std::uint16_t flags = check_header(r, bytes, options);
  if (!(flags & kRmbZstd)) return std::string(bytes);
  // The image: the header with the zstd bit cleared, the frame's content, the stored CRC-32
  // (already checked over the compressed file). Offsets inside it are those of the image.
  std::string image(bytes.substr(0, kHeader));
  const std::uint16_t plain = flags & ~kRmbZstd;
  image[6] = char(plain & 0xFF);
  image[7] = char(plain >> 8);
  image += rmb_zstd_decompress(bytes.substr(kHeader, body_end - kHeader), kHeader,
                               kMaxFile - kHeader - kTrailer);
  image += bytes.substr(body_end);
  return image;
}

ir::Grammar decode_rmb(std::string_view bytes, const RmbDecodeOptions& options,
                       std::vector<rmb::TraceEntry>* trace) {
  return decode_rmb_contents(bytes, options, trace).grammar;
}

RmbContents decode_rmb_contents(std::string_view bytes, const RmbDecodeOptions& options,
                                std::vector<rmb::TraceEntry>* trace) {
  if (bytes.size() >= kHeader && (std::uint8_t(bytes[6]) & kRmbZstd)) {
    const std::string image = rmb_uncompressed(bytes, options);
    RmbDecodeOptions inner = options;
    inner.verify_checksum = false;  // checked over the compressed file
    return decode_rmb_contents(image, inner, trace);
  }
  Decoder d{};
  d.bytes = bytes;
  d.trace = trace;
  d.g = ir::make_grammar("");  // the turtle symbols are implied
  const std::size_t body_end = bytes.size() >= kTrailer ? bytes.size() - kTrailer : 0;
  Reader r(bytes, 0, body_end, trace);
  r.heading("header");
  const std::uint16_t flags = check_header(r, bytes, options);
  d.version = std::uint8_t(bytes[4]) | (std::uint8_t(bytes[5]) << 8);
  d.quantized = flags & kRmbQuantized;
  d.stripped = flags & kRmbStripped;
  const std::size_t count_at = r.pos();
  const std::size_t n = r.count("section count", 255, 3);
  // Sections 1..9 always; then the optional 10 (piece sets), 11 (voxel rule tables) and 12
  // (placed pieces).
  if (n < kSectionCount || n > kSectionCount + 3) {
    r.fail_at(count_at, "expected 9 to 12 sections, found " + std::to_string(n));
  }
  std::size_t expect_at = 0;  // sections are contiguous, right after the table
  std::vector<std::pair<std::size_t, std::size_t>> ranges;
  std::vector<std::size_t> ids;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t at = r.pos();
    const std::uint64_t id = r.varint("section id");
    const bool ok = i < kSectionCount
                        ? id == i + 1
                        : id >= std::size_t(RmbSection::Pieces) &&
                              id <= std::size_t(RmbSection::PieceStream) && id > ids.back();
    if (!ok) {
      const std::string want = i < kSectionCount
                                   ? std::to_string(i + 1) + " (" + section_name(i + 1) + ")"
                               : ids.back() < std::size_t(RmbSection::Pieces)
                                   ? "10 (piece sets), 11 (voxel rule tables) or 12 (placed pieces)"
                               : ids.back() < std::size_t(RmbSection::VoxelRules)
                                   ? "11 (voxel rule tables) or 12 (placed pieces)"
                                   : "12 (placed pieces)";
      r.fail_at(at, "expected section id " + want + ", found " + std::to_string(id));
    }
    ids.push_back(std::size_t(id));
    const std::uint64_t off = r.varint("offset");
    const std::uint64_t len = r.bounded("length", body_end);
    if (i > 0 && off != expect_at)
      r.fail_at(at, "expected section offset " + std::to_string(expect_at));
    if (off > body_end || len > body_end - off) r.fail_at(at, "expected a section inside the file");
    ranges.emplace_back(std::size_t(off), std::size_t(off + len));
    expect_at = std::size_t(off + len);
  }
  if (ranges.front().first != r.pos()) r.fail("expected the first section right after the table");
  if (expect_at != body_end)
    r.fail_at(expect_at, "expected the CRC-32 right after the last section");
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t id = ids[i];
    Reader s = d.section(ranges[i].first, ranges[i].second);
    s.heading(std::string("section ") + std::to_string(id) + ": " + section_name(id));
    d.run_section(RmbSection(id), s);
    if (!s.at_end())
      s.fail("expected the end of the section, found " + std::to_string(s.left()) +
             " more byte(s)");
  }
  if (trace) {
    Reader tail(bytes, body_end, bytes.size(), trace);
    tail.heading("trailer");
    tail.u32("crc32");
  }
  if (!rmb_has_lsystem(d.g) && (!d.g.productions.empty() || !d.g.axiom.empty())) {
    throw RmbError(ranges.front().first,
                   "expected a named lsystem block: the grammar has " +
                       std::string(d.g.productions.empty() ? "an axiom" : "productions"));
  }
  verify_rmb_codes(d.g, d.code_at);
  if (d.stripped) d.name_stripped_locations();
  d.g.build_tables();
  return RmbContents{std::move(d.g), std::move(d.voxels), std::move(d.pieces), std::move(d.placed)};
}

std::string format_rmb_trace(std::string_view bytes, const std::vector<rmb::TraceEntry>& trace) {
  std::string out;
  char buf[32];
  for (const rmb::TraceEntry& e : trace) {
    if (e.size == 0) {
      out += "-- " + e.field + "\n";
      continue;
    }
    std::snprintf(buf, sizeof buf, "%08zx  ", e.offset);
    std::string hex = rmb::hex_bytes(bytes.substr(e.offset, e.size), 8);
    hex.resize(std::max<std::size_t>(hex.size(), 26), ' ');
    std::string field = e.field;
    field.resize(std::max<std::size_t>(field.size(), 22), ' ');
    out += buf + hex + "  " + field + "  " + e.value + "\n";
  }
  return out;
}

std::string rmb_stripped_location(std::size_t production) {
  return "production " + std::to_string(production);
}

}  // namespace ramus
