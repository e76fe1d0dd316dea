// A command's refinement options from the registry's records (operation_options.hpp).
#include "operation_options.hpp"

#include "console.hpp"

namespace meshstep::app {
namespace {

// The run description's own check of one value, as a CLI11 validator: CLI11 then names the
// option ("--max-area: must be a positive number, not -1").
CLI::Validator value_check(OperationKind kind, const ParameterInfo& parameter) {
  return CLI::Validator(
      [kind, &parameter](std::string& text) -> std::string {
        Operation scratch;
        scratch.kind = kind;
        try {
          set_option(scratch, parameter.name, text);
        } catch (const RunSpecError& e) {
          const std::string what = e.what();
          const std::string prefix = "--" + std::string(parameter.name) + ": ";
          return what.starts_with(prefix) ? what.substr(prefix.size()) : what;
        }
        return {};
      },
      "");
}

}  // namespace

std::string option_help(OperationKind kind, const ParameterInfo& parameter) {
  std::string help(help_for(kind, parameter));
  if (parameter.kind != ParameterKind::choice || parameter.choice_source == ChoiceSource::own) return help;
  std::string words;
  for (const std::string& w : accepted_words(kind, parameter)) words += (words.empty() ? "" : ", ") + w;
  return help + ": " + words;
}

OperationOptions::OperationOptions(CLI::App& cmd, OperationKind kind) : kind_(kind) {
  for (const ParameterInfo& p : refine_parameters()) {
    if (!takes(kind, p)) continue;
    auto entry = std::make_unique<Entry>();
    entry->parameter = &p;
    const std::string names =
        (p.short_name.empty() ? "" : "-" + std::string(p.short_name) + ",") + "--" + std::string(p.name);
    if (p.kind == ParameterKind::flag) {
      entry->option = cmd.add_flag(names, entry->flag, option_help(kind, p));
    } else {
      entry->text = std::string(p.default_text);
      entry->option = cmd.add_option(names, entry->text, option_help(kind, p));
      if (p.kind == ParameterKind::choice)
        entry->option->check(CLI::IsMember(accepted_words(kind, p)));
      else
        entry->option->check(value_check(kind, p));
      if (!p.type_name.empty()) entry->option->type_name(std::string(p.type_name));
      if (!p.default_text.empty()) entry->option->capture_default_str();
    }
    entries_.push_back(std::move(entry));
  }
  if (kind != OperationKind::refine) return;
  region_box_ = std::make_unique<Entry>();
  region_box_->option =
      cmd.add_option("--region", region_box_->text,
                     "Refine only where a triangle's centroid lies in the box X0,Y0,X1,Y1 (border\n"
                     "included); elsewhere triangles are held to no bound, and change only where\n"
                     "the algorithm's own rules reach them (docs/recipes.md, Regions)")
          ->type_name("X0,Y0,X1,Y1");
  region_polygon_ = std::make_unique<Entry>();
  region_polygon_->option =
      cmd.add_option("--region-polygon", region_polygon_->text,
                     "As --region, in the simple polygon through these vertices, in order (at\n"
                     "least 3; the last joins the first): the recipe keeps it in its own line")
          ->type_name("X0,Y0,X1,Y1,X2,Y2,...");
  region_poly_ = std::make_unique<Entry>();
  region_poly_->option = cmd.add_option("--region-poly", region_poly_->text,
                                        "As --region, in the polygon the segments of FILE.poly make (one closed\n"
                                        "simple polygon; its holes and regions are not used)")
                             ->type_name("FILE.poly");
}

std::optional<Operation> OperationOptions::operation() const {
  Operation op;
  op.kind = kind_;
  try {
    for (const auto& e : entries_)
      if (e->option->count() > 0)
        set_option(op, e->parameter->name, e->parameter->kind == ParameterKind::flag ? "" : e->text);
    if (region_box_ && region_box_->option->count() > 0) set_option(op, "region", region_box_->text);
    if (region_polygon_ && region_polygon_->option->count() > 0)
      set_option(op, "region-polygon", region_polygon_->text);
    if (region_poly_ && region_poly_->option->count() > 0) set_option(op, "region-poly", region_poly_->text);
  } catch (const RunSpecError& e) {
    print_error(e.what());
    return std::nullopt;
  }
  return op;
}

std::vector<std::string> OperationOptions::given() const {
  std::vector<std::string> names;
  for (const auto& e : entries_)
    if (e->option->count() > 0) names.push_back("--" + std::string(e->parameter->name));
  return names;
}

}  // namespace meshstep::app
