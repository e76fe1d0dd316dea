// The replay log of a run, opened with its header: what the command line's --record and
// the viewer's workbench (which records every re-mesh) both write, so that a log made in
// the window reads as one made by `meshstep run`.
#pragma once

#include <memory>
#include <string>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/replay/log_writer.hpp"

namespace meshstep::app {

// Opens the log for a run of `algorithm` on the file `input`, read as `pslg` (whose
// regions, holes, markers and attributes the header keeps, so that a moment of the run can
// be written as the run writes its output). Throws InputError.
// pslg: null for an input that is not a PSLG (a height grid). recipe_lines: a recipe's
// operations, one a line (LogHeader::operations), for a run of more than one.
inline std::unique_ptr<replay::LogWriter> open_log(const std::string& path, const std::string& input,
                                                   const std::string& algorithm, const std::string& parameters,
                                                   DataStructure ds, Insertion insertion, const Pslg* pslg,
                                                   const std::string& recipe_lines = "") {
  replay::LogHeader header;
  header.input = input;
  header.input_hash = replay::file_hash(input);
  header.algorithm = algorithm;
  header.parameters = parameters;
  header.data_structure = to_string(ds);
  header.insertion = to_string(insertion);
  header.operations = recipe_lines;
  if (pslg) replay::describe_input(header, *pslg);
  return std::make_unique<replay::LogWriter>(path, header);
}

}  // namespace meshstep::app
