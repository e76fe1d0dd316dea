#include "compare_with.hpp"

#include <imgui.h>

#include <cstdio>
#include <filesystem>

#include "meshstep/error.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {

CompareWith compare_with(const replay::LogReader& log, const std::string& words) {
  std::string text = words;
  // The words as refine takes them, with or without the command's name.
  if (text.rfind("refine", 0) != 0) text = "refine " + text;
  CompareWith out;
  out.refine.operation = parse_operation(text);
  if (out.refine.operation->kind != OperationKind::refine)
    throw RunSpecError("compare with: a refinement (refine --algorithm NAME ...), not '" + words + "'");
  out.base_log = log.path();
  out.input = log.header().input;
  std::error_code ec;
  if (out.input.empty()) throw InputError(log.path(), 0, "its header names no input to run again");
  if (!std::filesystem::exists(out.input, ec))
    throw InputError(out.input, 0, "the input of " + log.path() + " is not there any more (run it again by hand)");
  return out;
}

std::string suggested_comparison(const replay::LogReader& log) {
  const std::string other = log.header().algorithm == "circumcenter" ? "offcenter" : "circumcenter";
  std::string words = "--algorithm " + other;
  char bound[64];
  if (const auto& a = log.run().min_angle; a && *a > 0.0) {
    std::snprintf(bound, sizeof bound, " --min-angle %.6g", *a);
    words += bound;
  }
  return words;
}

void draw_compare_with(Viewer& viewer, char* words, std::size_t size) {
  const replay::LogReader* log = viewer.session().log();
  if (!log || !ImGui::CollapsingHeader("Compare with...")) return;
  ImGui::TextWrapped("Run this input again with other options, live, then see both side by side:");
  if (words[0] == '\0') std::snprintf(words, size, "%s", suggested_comparison(*log).c_str());
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputText("##compare_words", words, size);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("as refine takes them: --algorithm, --min-angle, --ds dcel, --insertion cavity...");
  ImGui::PopStyleColor();
  if (ImGui::Button("Run and compare")) viewer.compare_words = words;
}

}  // namespace meshstep::viewer
