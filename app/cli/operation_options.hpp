// A command's refinement options, made from the registry's parameter records
// (refine/registry.hpp): each record becomes a CLI11 option with its help, range check and
// words, and what the command line gave becomes an Operation (refine/run_spec.hpp) through
// the run description's own parser. No command keeps a copy of the options' handling.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "meshstep/refine/registry.hpp"
#include "meshstep/refine/run_spec.hpp"

namespace meshstep::app {

class OperationOptions {
 public:
  // Adds --NAME to `cmd` for every parameter an operation of `kind` takes.
  OperationOptions(CLI::App& cmd, OperationKind kind);

  // The operation the command line gave, once CLI11 has parsed it; nothing, after saying
  // why on standard error, when its options cannot be run together (a usage error).
  std::optional<Operation> operation() const;
  // The names (with dashes) of the options given on the command line.
  std::vector<std::string> given() const;

 private:
  struct Entry {
    const ParameterInfo* parameter = nullptr;
    CLI::Option* option = nullptr;
    std::string text;   // a value's text
    bool flag = false;  // a flag's
  };
  OperationKind kind_;
  std::vector<std::unique_ptr<Entry>> entries_;  // stable: CLI11 writes into them
  // --region, --region-polygon and --region-poly (a refinement's only; not registry parameters).
  std::unique_ptr<Entry> region_box_, region_polygon_, region_poly_;
};

// The help of a parameter for an operation of `kind`; a choice whose words come from a
// registry table lists them: "Override the algorithm's choice of new vertex: circumcenter,
// offcenter, ...".
std::string option_help(OperationKind kind, const ParameterInfo& parameter);

}  // namespace meshstep::app
