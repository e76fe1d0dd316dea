// --record LOG, shared by every command that runs an algorithm (the log itself is opened
// by common/run_log.hpp, which the viewer's workbench shares).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "common/run_log.hpp"
#include "meshstep/replay/log_writer.hpp"

namespace meshstep::app {

inline void add_record_option(CLI::App& cmd, std::string& path) {
  cmd.add_option("--record", path,
                 "Record every step of the run into the replay log LOG (written as the run\n"
                 "goes, to LOG.partial, renamed to LOG when the run ends; see 'meshstep log')")
      ->type_name("LOG");
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
