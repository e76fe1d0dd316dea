// What a command reads and what it writes, checked before any work (issue 31): an output
// that is one of the inputs would replace the user's file with the result, and two outputs
// that are one file would keep only the last. Files are compared by device and inode, so a
// path spelt another way (./x, a/../x), a symlink or a hard link is caught as well.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace meshstep::app {

class FileRoles {
 public:
  // A file the command reads. One that does not exist is no clash (its reader says so).
  FileRoles& reads(const std::string& path);
  // A .poly or .node input, and the .node beside a .poly that may hold its vertices.
  FileRoles& reads_pslg(const std::string& path);
  // A mesh PREFIX: every file of it that a reader may open (.node, .ele, .poly, .area).
  FileRoles& reads_mesh(const std::string& prefix);

  // One file written, as the command line names it: `option value` (option "" for a
  // default name); `noun` says what to choose instead ("output prefix", "log", ...).
  // An empty path: nothing written.
  FileRoles& writes(const std::string& option, const std::string& path, const std::string& noun);
  // Every file a mesh prefix expands to (.node .ele .poly .area .edge .neigh); `given`:
  // the option's value when it is not the prefix itself (terrain's -o tin.node).
  FileRoles& writes_mesh(const std::string& option, const std::string& prefix, const std::string& given = "");
  // A replay log: LOG, and LOG.partial while the run goes.
  FileRoles& writes_log(const std::string& option, const std::string& path);
  // Files of one output that already exist, e.g. numbered tiles or frames (written
  // files that do not exist yet cannot be an input).
  FileRoles& writes_existing(const std::string& option, const std::string& value, const std::vector<std::string>& paths,
                             const std::string& noun);

  // The first clash, said as the error to print, or nothing.
  std::optional<std::string> clash() const;

 private:
  struct Output {
    std::string option, value, path, noun;
    std::size_t group;  // one per call: a prefix's own files do not clash with each other
  };
  FileRoles& add_output(const std::string& option, const std::string& value, const std::string& path,
                        const std::string& noun);
  std::vector<std::string> inputs_;
  std::vector<Output> outputs_;
  std::size_t groups_ = 0;
};

}  // namespace meshstep::app
