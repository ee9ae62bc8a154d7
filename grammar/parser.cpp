// The one translation unit that includes Spirit X3: it instantiates the grammar of
// grammar/detail/rules_def.h and drives it with error recovery.
//
// The driver parses a file one declaration at a time, and a block (`lsystem`, `pieces`,
// `voxels`) one item at a time: after a syntax error it reports "expected X" and skips to the
// next `;` or `}` at the same nesting (grammar/detail/scan.cpp), so each broken item costs one
// diagnostic and the rest of the file is still parsed and checked.
#include "grammar/parser.h"

#include <algorithm>
#include <string>
#include <string_view>

#include "grammar/detail/rules_def.h"
#include "grammar/detail/scan.h"

namespace ramus::parser {

BOOST_SPIRIT_INSTANTIATE(block_head_type, iterator_type, context_type)
BOOST_SPIRIT_INSTANTIATE(simple_decl_type, iterator_type, context_type)
BOOST_SPIRIT_INSTANTIATE(ls_item_type, iterator_type, context_type)
BOOST_SPIRIT_INSTANTIATE(piece_item_type, iterator_type, context_type)
BOOST_SPIRIT_INSTANTIATE(voxel_item_type, iterator_type, context_type)

}  // namespace ramus::parser

namespace ramus {

namespace {

using parser::iterator_type;

// X3 names what it expected as `';'` or `"->"`; diagnostics quote with single quotes.
std::string describe(const std::string& which) {
  if (which.size() >= 2 && (which.front() == '"' || which.front() == '\'') &&
      which.back() == which.front()) {
    return "'" + which.substr(1, which.size() - 2) + "'";
  }
  return which;
}

// A missing `;` (or closing quote) is reported right after the previous token, where it
// belongs and on its line; anything else at the token that is there instead.
bool is_terminator(const std::string& what) { return what == "';'" || what == "'\"'"; }

class Driver {
 public:
  Driver(SourceManager& sm, std::uint32_t file, DiagnosticSink& diags)
      : diags_(diags), text_(sm.text(file)), file_(file) {
    state_.base = text_.data();
    state_.file = file;
  }

  ast::File run(std::size_t start) {
    ast::File f;
    f.file_id = file_;
    for (std::size_t pos = start;;) {
      pos = detail::skip_trivia(text_, pos);
      if (pos >= text_.size()) break;
      std::size_t next = declaration(pos, f);
      // Recovery may stop before a declaration keyword; never where this declaration began.
      pos = next > pos ? next : std::max(pos + 1, detail::recover_in_block(text_, pos + 1));
    }
    return f;
  }

  SourceSpan span_at(std::size_t p, std::size_t len) const {
    return {file_, std::uint32_t(p), std::uint32_t(p + len)};
  }

 private:
  enum class Outcome { Ok, NoMatch, Failed };

  // Runs one entry rule at `pos`. On success `pos` moves past it; on a reported error `pos` is
  // where recovery starts.
  template <typename Rule, typename Attr>
  Outcome attempt(Rule const& rule, std::size_t& pos, Attr& attr) {
    const char* first = text_.data() + pos;
    const char* last = text_.data() + text_.size();
    state_.depth = 0;
    auto skipper_ctx = parser::x3::make_context<parser::x3::skipper_tag>(parser::trivia);
    std::reference_wrapper<parser::ParseState> ref = std::ref(state_);
    parser::context_type ctx(ref, skipper_ctx);
    try {
      if (!rule.parse(first, last, ctx, parser::x3::unused, attr)) return Outcome::NoMatch;
      pos = std::size_t(first - text_.data());
      return Outcome::Ok;
    } catch (parser::x3::expectation_failure<iterator_type> const& x) {
      std::string what = describe(x.which());
      pos = std::size_t(x.where() - text_.data());
      expected(pos, what, is_terminator(what));
    } catch (parser::NestingError const& e) {
      pos = detail::skip_trivia(text_, std::size_t(e.where - text_.data()));
      diags_.report(
          DiagCode::NestingTooDeep, span_at(pos, detail::token_length(text_, pos)),
          "expression nested deeper than " + std::to_string(detail::kMaxNesting) + " levels");
    }
    return Outcome::Failed;
  }

  void expected(std::size_t pos, const std::string& what, bool after_previous) {
    pos = detail::skip_trivia(text_, pos);
    std::string msg = "expected " + what;
    if (pos >= text_.size()) {
      msg += " at the end of the file";
      after_previous = true;
    }
    if (after_previous) {
      diags_.report(DiagCode::SyntaxError, span_at(detail::end_of_previous_token(text_, pos), 0),
                    msg);
      return;
    }
    diags_.report(DiagCode::SyntaxError, span_at(pos, detail::token_length(text_, pos)), msg);
  }

  std::size_t declaration(std::size_t pos, ast::File& f) {
    parser::BlockHead head;
    std::size_t p = pos;
    switch (attempt(parser::block_head(), p, head)) {
      case Outcome::Ok:
        return block(head, p, f);
      case Outcome::Failed:
        return detail::recover_at_file_level(text_, p);
      case Outcome::NoMatch:
        break;
    }
    ast::Decl decl;
    p = pos;
    switch (attempt(parser::simple_decl(), p, decl)) {
      case Outcome::Ok:
        f.decls.push_back(std::move(decl));
        return p;
      case Outcome::Failed:
        return detail::recover_at_file_level(text_, p);
      case Outcome::NoMatch:
        break;
    }
    expected(pos, "declaration (import, const, param, module, lsystem, pieces or voxels)", false);
    return detail::recover_at_file_level(text_, pos);
  }

  std::size_t block(parser::BlockHead& head, std::size_t pos, ast::File& f) {
    switch (head.kind) {
      case parser::BlockKind::LSystem:
        return items<ast::LSystem, ast::LSystemItem>(parser::ls_item(), head, pos, f,
                                                     "production or lsystem setting");
      case parser::BlockKind::Pieces:
        return items<ast::Pieces, ast::PiecesItem>(parser::piece_item(), head, pos, f,
                                                   "rim, piece, attach rule or setting");
      case parser::BlockKind::Voxels:
        return items<ast::Voxels, ast::VoxelsItem>(parser::voxel_item(), head, pos, f,
                                                   "voxel rule or setting");
    }
    return pos;
  }

  // { item } "}" -- one item at a time, recovering inside the block.
  template <typename Block, typename Item, typename Rule>
  std::size_t items(Rule const& rule, parser::BlockHead& head, std::size_t pos, ast::File& f,
                    const char* what) {
    Block b;
    b.name = std::move(head.name);
    b.span = head.span;
    for (;;) {
      pos = detail::skip_trivia(text_, pos);
      if (pos >= text_.size()) {
        expected(pos, "'}'", true);
        diags_.note(span_at(b.span.begin, 0), "the block starts here");
        break;
      }
      if (text_[pos] == '}') {
        ++pos;
        break;
      }
      Item item;
      std::size_t p = pos;
      Outcome r = attempt(rule, p, item);
      if (r == Outcome::Ok) {
        b.items.push_back(std::move(item));
        pos = p;
        continue;
      }
      if (r == Outcome::NoMatch) {
        expected(pos, what, false);
        p = pos;
      }
      std::size_t next = detail::recover_in_block(text_, p);
      pos = next > pos ? next : pos + 1;  // always make progress
    }
    b.span.end = std::uint32_t(pos);
    f.decls.push_back(std::move(b));
    return pos;
  }

  DiagnosticSink& diags_;
  std::string_view text_;
  std::uint32_t file_;
  parser::ParseState state_;
};

}  // namespace

ast::File parse(SourceManager& sm, std::uint32_t file_id, DiagnosticSink& diags) {
  std::string_view text = sm.text(file_id);
  detail::ScanResult scan = detail::prescan(text, file_id);
  Driver driver(sm, file_id, diags);
  if (scan.bad_byte) {
    std::size_t p = *scan.bad_byte;
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", unsigned(static_cast<unsigned char>(text[p])));
    std::string why = text[p] == '\0' ? "a NUL byte"
                                      : "a byte that is not valid UTF-8 (" + std::string(hex) + ")";
    diags.report(DiagCode::BinaryInput, driver.span_at(p, 1),
                 "file is not UTF-8 text: " + why + " at byte offset " + std::to_string(p));
    ast::File empty;
    empty.file_id = file_id;
    return empty;
  }
  if (scan.unterminated_comment) {
    diags.report(DiagCode::UnterminatedComment, driver.span_at(*scan.unterminated_comment, 2),
                 "unterminated block comment: '/*' without '*/'");
  }
  if (scan.too_deep) {
    diags.report(DiagCode::NestingTooDeep, driver.span_at(*scan.too_deep, 1),
                 "brackets and braces nested deeper than " + std::to_string(detail::kMaxNesting) +
                     " levels");
    ast::File f;
    f.file_id = file_id;
    f.comments = std::move(scan.comments);
    return f;
  }
  ast::File f = driver.run(scan.start);
  f.comments = std::move(scan.comments);
  return f;
}

}  // namespace ramus
