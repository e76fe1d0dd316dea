// --record LOG, shared by every command that runs an algorithm.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/replay/log_writer.hpp"

namespace meshstep::app {

inline void add_record_option(CLI::App& cmd, std::string& path) {
  cmd.add_option("--record", path,
                 "Record every step of the run into the replay log LOG (written as the run\n"
                 "goes, to LOG.partial, renamed to LOG when the run ends; see 'meshstep log')")
      ->type_name("LOG");
}

// Opens the log for a run of `algorithm` on the file `input`, read as `pslg` (whose
// regions, holes, markers and attributes the header keeps, so that a moment of the run can
// be written as the run writes its output). Throws InputError.
// pslg: null for an input that is not a PSLG (a height grid). recipe_lines: a recipe's
// operations, one a line (LogHeader::operations), for a run of more than one.
inline std::unique_ptr<replay::LogWriter> open_log(const std::string& path, const std::string& input,
                                                   const std::string& algorithm,
                                                   const std::string& parameters,
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

inline std::string record_summary(const replay::LogWriter& log) {
  const replay::LogStats& s = log.stats();
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "recorded %llu events in %llu steps to %s (%.2f MiB, %.1f bytes per event, %llu keyframes)",
                static_cast<unsigned long long>(s.events), static_cast<unsigned long long>(s.steps),
                log.path().c_str(), s.bytes / 1048576.0,
                s.events ? static_cast<double>(s.bytes) / s.events : 0.0,
                static_cast<unsigned long long>(s.keyframes));
  return buf;
}

}  // namespace meshstep::app
