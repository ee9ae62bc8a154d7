#include "lsp/protocol_json.h"

namespace ramus::lsp {

using nlohmann::json;

void to_json(json& j, const Position& p) { j = {{"line", p.line}, {"character", p.character}}; }

void to_json(json& j, const Range& r) { j = {{"start", r.start}, {"end", r.end}}; }

void to_json(json& j, const Location& l) { j = {{"uri", l.uri}, {"range", l.range}}; }

void to_json(json& j, const LspDiagnostic& d) {
  j = {{"range", d.range},
       {"severity", int(d.severity)},
       {"code", d.code},
       {"source", "ramus"},
       {"message", d.message}};
  if (!d.related.empty()) {
    json related = json::array();
    for (const RelatedInformation& r : d.related) {
      related.push_back({{"location", r.location}, {"message", r.message}});
    }
    j["relatedInformation"] = std::move(related);
  }
}

void to_json(json& j, const TextEdit& e) { j = {{"range", e.range}, {"newText", e.new_text}}; }

void to_json(json& j, const Hover& h) {
  j = {{"contents", {{"kind", "markdown"}, {"value", h.markdown}}}, {"range", h.range}};
}

void to_json(json& j, const CompletionItem& c) {
  j = {{"label", c.label}, {"kind", int(c.kind)}};
  if (!c.detail.empty()) j["detail"] = c.detail;
  if (!c.documentation.empty()) {
    j["documentation"] = {{"kind", "markdown"}, {"value", c.documentation}};
  }
}

void to_json(json& j, const DocumentSymbol& s) {
  j = {{"name", s.name},
       {"kind", int(s.kind)},
       {"range", s.range},
       {"selectionRange", s.selection_range}};
  if (!s.detail.empty()) j["detail"] = s.detail;
  if (!s.children.empty()) j["children"] = s.children;
}

}  // namespace ramus::lsp
