#include "grammar/program_constants.h"

#include <algorithm>
#include <cstdint>

namespace ramus {

namespace {

class ConstantCollector {
 public:
  ConstantCollector(const Program& program, const ConstantDefines& defines,
                    const ConstantFailure& on_failure)
      : prog_(program), defines_(defines), on_failure_(on_failure), seen_(program.files.size()) {}

  std::unordered_map<std::string, double> run() {
    visit(0);
    return std::move(values_);
  }

 private:
  void visit(std::uint32_t file) {
    if (file >= prog_.files.size() || seen_[file]) return;
    seen_[file] = 1;
    if (file < prog_.imports.size()) {
      for (std::uint32_t dep : prog_.imports[file]) visit(dep);
    }
    for (const ast::Decl& d : prog_.files[file].decls) {
      const auto* cd = std::get_if<ast::ConstDecl>(&d);
      if (!cd) continue;
      for (const ast::Binding& b : cd->bindings) {
        auto def = std::find_if(defines_.begin(), defines_.end(),
                                [&](const auto& x) { return x.first == b.name.name; });
        if (cd->is_param && def != defines_.end()) {
          values_[b.name.name] = def->second;
          continue;
        }
        const FoldResult r = evaluate_constant(b.value, lookup_in(values_));
        if (r.value) {
          values_[b.name.name] = *r.value;
        } else if (on_failure_) {
          on_failure_(b.value, r);
        }
      }
    }
  }

  const Program& prog_;
  const ConstantDefines& defines_;
  const ConstantFailure& on_failure_;
  std::vector<std::uint8_t> seen_;
  std::unordered_map<std::string, double> values_;
};

}  // namespace

std::unordered_map<std::string, double> program_constants(const Program& program,
                                                          const ConstantDefines& defines,
                                                          const ConstantFailure& on_failure) {
  return ConstantCollector(program, defines, on_failure).run();
}

ConstLookup lookup_in(const std::unordered_map<std::string, double>& values) {
  return [&values](std::string_view n) -> std::optional<double> {
    auto it = values.find(std::string(n));
    if (it == values.end()) return std::nullopt;
    return it->second;
  };
}

}  // namespace ramus
