// The canonical layout (docs/formatting.md). Declarations and block items are printed one per
// line by detail/format_parts.cpp; this file places them and the comments:
//  - a comment before an item stays before it, on its own line at the item's indentation;
//  - a comment after an item on the same line stays there (two spaces before it);
//  - a comment inside an item (e.g. between two bindings of one `const`) moves to its own line
//    before the item, except one that ends the line of a stochastic alternative, which stays
//    after that alternative;
//  - one blank line is kept wherever the source had at least one, except right after `{`.
#include "grammar/format.h"

#include "grammar/detail/format_parts.h"

namespace ramus {
namespace {

using namespace detail;

template <typename V>
SourceSpan span_of(const V& item) {
  return std::visit([](const auto& x) { return x.span; }, item);
}

bool is_block(const ast::Decl& d) {
  return std::holds_alternative<ast::LSystem>(d) || std::holds_alternative<ast::Pieces>(d) ||
         std::holds_alternative<ast::Voxels>(d);
}

std::string trimmed(const std::string& s) {
  std::size_t e = s.size();
  while (e > 0 && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r' || s[e - 1] == '\n')) {
    --e;
  }
  return s.substr(0, e);
}

class Printer {
 public:
  Printer(const ast::File& file, std::string_view text, bool has_source)
      : file_(file), text_(text), has_source_(has_source) {}

  std::string run() {
    bool first = true;
    const ast::Decl* prev = nullptr;
    const std::uint32_t eof = std::uint32_t(text_.size()) + 1;
    for (std::size_t i = 0; i < file_.decls.size(); ++i) {
      const ast::Decl& d = file_.decls[i];
      SourceSpan sp = span_of(d);
      leading(sp.begin, 0, first);
      if (has_source_) {
        blank_if_gap(sp.begin, first);
      } else if (prev && (is_block(d) || is_block(*prev) || d.index() != prev->index())) {
        out_ += "\n";
      }
      decl(d);
      trailing(sp.end, i + 1 < file_.decls.size() ? span_of(file_.decls[i + 1]).begin : eof);
      first = false;
      prev = &d;
    }
    leading(eof, 0, first);
    return out_;
  }

 private:
  // ---- comments and blank lines ----

  bool has_comment_before(std::uint32_t pos) const {
    return next_ < file_.comments.size() && file_.comments[next_].span.begin < pos;
  }

  void blank_if_gap(std::uint32_t pos, bool first) {
    if (first || prev_end_ >= pos || pos > text_.size()) return;
    std::string_view gap = text_.substr(prev_end_, pos - prev_end_);
    int newlines = 0;
    for (char c : gap) newlines += c == '\n';
    if (newlines >= 2) out_ += "\n";
  }

  void comment_line(const ast::Comment& c, int indent) {
    out_ += std::string(2 * indent, ' ') + trimmed(c.text) + "\n";
    prev_end_ = c.span.end;
    closed_line_end_ = out_.size(), closed_line_indent_ = std::size_t(2 * indent);
  }

  static bool is_line_comment(const ast::Comment& c) { return c.text.rfind("//", 0) == 0; }

  // Comments that start before `pos`, each on its own line.
  void leading(std::uint32_t pos, int indent, bool& first) {
    while (has_comment_before(pos)) {
      const ast::Comment& c = file_.comments[next_++];
      blank_if_gap(c.span.begin, first);
      comment_line(c, indent);
      first = false;
    }
  }

  bool same_line(std::uint32_t from, std::uint32_t to) const {
    if (from > to || to > text_.size()) return false;
    return text_.substr(from, to - from).find('\n') == std::string_view::npos;
  }

  // Comments after `end` on the same line, and before `limit` (where the next code starts), go
  // at the end of the line just printed.
  void trailing(std::uint32_t end, std::uint32_t limit) {
    prev_end_ = std::max(prev_end_, end);
    bool any = false;
    while (next_ < file_.comments.size() && file_.comments[next_].span.begin < limit &&
           same_line(end, file_.comments[next_].span.begin)) {
      const ast::Comment& c = file_.comments[next_++];
      if (out_.size() == closed_line_end_) {
        // The line just printed ends in a `//` comment (a comment moved before the code's end,
        // such as one after a rule's last alternative when its `;` follows on the next line):
        // appended, this comment would become part of that one. Or it is a comment moved there
        // on a line of its own, which the next run keeps on its own line, apart from this one.
        // Either way this comment gets a line of its own, at that line's indentation (where a
        // block comment over several lines starts, not its last line's).
        out_ += std::string(closed_line_indent_, ' ') + trimmed(c.text) + "\n";
        closed_line_end_ = out_.size();
      } else {
        out_.pop_back();  // the newline
        out_ += (any ? " " : "  ") + trimmed(c.text) + "\n";
        if (is_line_comment(c)) {
          const std::size_t start = out_.rfind('\n', out_.size() - 2) + 1;  // npos + 1 == 0
          closed_line_end_ = out_.size();
          closed_line_indent_ = out_.find_first_not_of(' ', start) - start;
        }
      }
      end = prev_end_ = c.span.end;
      any = true;
    }
  }

  // ---- items ----

  void line(int indent, const std::string& s) { out_ += std::string(2 * indent, ' ') + s + "\n"; }

  // A one-line item: comments inside it move before it.
  void simple(const std::string& s, SourceSpan sp, int indent) {
    leading(sp.end, indent, hoisted_first_);
    line(indent, s);
  }

  void decl(const ast::Decl& d) {
    SourceSpan sp = span_of(d);
    hoisted_first_ = true;
    if (const auto* x = std::get_if<ast::Import>(&d)) return simple(fmt_import(*x), sp, 0);
    if (const auto* x = std::get_if<ast::ConstDecl>(&d)) return simple(fmt_const(*x), sp, 0);
    if (const auto* x = std::get_if<ast::ModuleDecl>(&d)) return simple(fmt_module_decl(*x), sp, 0);
    if (const auto* x = std::get_if<ast::LSystem>(&d))
      return block("lsystem", x->name, x->items, sp);
    if (const auto* x = std::get_if<ast::Pieces>(&d)) return block("pieces", x->name, x->items, sp);
    if (const auto* x = std::get_if<ast::Voxels>(&d)) return block("voxels", x->name, x->items, sp);
  }

  // The offset of the `{` after a block's name (comments skipped), or the name's end.
  std::uint32_t open_brace(const ast::Identifier& name) const {
    std::size_t p = name.span.end;
    while (p < text_.size()) {
      if (text_.compare(p, 2, "//") == 0) {
        p = text_.find('\n', p);
        if (p == std::string_view::npos) break;
      } else if (text_.compare(p, 2, "/*") == 0) {
        p = text_.find("*/", p + 2);
        if (p == std::string_view::npos) break;
        p += 2;
        continue;
      } else if (text_[p] == '{') {
        return std::uint32_t(p);
      }
      ++p;
    }
    return name.span.end;
  }

  template <typename Item>
  void block(const char* keyword, const ast::Identifier& name, const std::vector<Item>& items,
             SourceSpan sp) {
    std::uint32_t brace = has_source_ ? open_brace(name) : 0;
    leading(brace, 0, hoisted_first_);  // comments in the header move before it
    std::string head = std::string(keyword) + " " + name.name + " {";
    if (items.empty() && !has_comment_before(sp.end)) return line(0, head + "}");
    line(0, head);
    // A comment on the line of `{` stays there (but not one after an item on that line).
    prev_end_ = std::max(prev_end_, brace + 1);
    trailing(brace + 1, items.empty() ? sp.end : span_of(items.front()).begin);
    bool first = true;
    for (std::size_t i = 0; i < items.size(); ++i) {
      const Item& item = items[i];
      SourceSpan isp = span_of(item);
      leading(isp.begin, 1, first);
      blank_if_gap(isp.begin, first);
      hoisted_first_ = true;
      std::visit([&](const auto& x) { this->item(x, isp); }, item);
      trailing(isp.end, i + 1 < items.size() ? span_of(items[i + 1]).begin : sp.end);
      first = false;
    }
    leading(sp.end, 1, first);
    line(0, "}");
  }

  void item(const ast::Setting& x, SourceSpan sp) { simple(fmt_setting(x), sp, 1); }
  void item(const ast::Axiom& x, SourceSpan sp) {
    leading(sp.end, 1, hoisted_first_);
    wrapped("  axiom", fmt_modules(x.modules), ";");
  }
  void item(const ast::SymbolSet& x, SourceSpan sp) { simple(fmt_symbol_set(x), sp, 1); }
  void item(const ast::Select& x, SourceSpan sp) { simple(fmt_select(x), sp, 1); }
  void item(const ast::RimDecl& x, SourceSpan sp) { simple(fmt_rim(x), sp, 1); }
  void item(const ast::PieceDecl& x, SourceSpan sp) { simple(fmt_piece(x), sp, 1); }
  void item(const ast::AttachRule& x, SourceSpan sp) { simple(fmt_attach(x), sp, 1); }
  void item(const ast::PieceSetting& x, SourceSpan sp) { simple(fmt_piece_setting(x), sp, 1); }
  void item(const ast::VoxelSetting& x, SourceSpan sp) { simple(fmt_voxel_setting(x), sp, 1); }
  void item(const ast::VoxelRule& x, SourceSpan sp) { simple(fmt_voxel_rule(x), sp, 1); }

  // Module sequences longer than a line: wrap_modules (format.h).
  void wrapped(const std::string& prefix, const std::vector<std::string>& modules,
               const std::string& suffix) {
    out_ += wrap_modules(prefix, modules, suffix);
  }

  static std::string with(const std::string& a, const std::string& b) {
    return b.empty() ? a : a + " " + b;
  }

  // One alternative per line when there are several:
  //   F -> (0.33) F[+F]F[-F]F
  //       | (0.67) F[+F]F;
  void item(const ast::Production& p, SourceSpan sp) {
    const auto& alts = p.alternatives;
    const std::string head = "  " + fmt_production_head(p);
    if (alts.size() <= 1) {
      leading(sp.end, 1, hoisted_first_);
      if (alts.empty()) return wrapped(head, {}, ";");
      return wrapped(with(head, fmt_probability(alts[0])), fmt_modules(alts[0].successor), ";");
    }
    // Comments before the first alternative move before the production.
    leading(alts[0].span.begin, 1, hoisted_first_);
    for (std::size_t i = 0; i < alts.size(); ++i) {
      bool last = i + 1 == alts.size();
      std::string prefix = i == 0 ? head + " " : std::string("      | ");
      wrapped(prefix + fmt_probability(alts[i]), fmt_modules(alts[i].successor), last ? ";" : "");
      if (last) break;
      // A comment ending this alternative's line stays there; others move before the next
      // line (comments never move past code they preceded).
      trailing(alts[i].span.end, alts[i + 1].span.begin);
      leading(alts[i + 1].span.begin, 3, hoisted_first_);
    }
    leading(sp.end, 1, hoisted_first_);
  }

  const ast::File& file_;
  std::string_view text_;
  bool has_source_;
  std::string out_;
  std::size_t next_ = 0;        // the next comment to place
  std::uint32_t prev_end_ = 0;  // where the last placed code or comment ends in the source
  // The size of out_ right after the last line to which no comment may be appended: one that
  // ends in a `//` comment (an appended comment would become part of it), or one that holds only
  // comments (the next run keeps those on a line of their own); npos when none was printed.
  std::size_t closed_line_end_ = std::string::npos;
  std::size_t closed_line_indent_ = 0;  // the indentation that line starts with
  bool hoisted_first_ = true;           // no blank line before a moved comment
};

}  // namespace

std::string format_file(const ast::File& file, const SourceManager& sources) {
  std::string_view text = file.file_id < sources.size()
                              ? std::string_view(sources.text(file.file_id))
                              : std::string_view();
  return Printer(file, text, true).run();
}

std::string format_file(const ast::File& file) {
  ast::File bare = file;
  bare.comments.clear();
  return Printer(bare, std::string_view(), false).run();
}

std::string format_expr(const ast::Expr& expr) { return fmt_expr(expr); }

}  // namespace ramus
