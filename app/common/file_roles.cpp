#include "common/file_roles.hpp"

#include <sys/stat.h>

#include <filesystem>

#include "common/output_prefix.hpp"
#include "meshstep/io/formats.hpp"

namespace meshstep::app {
namespace {

// Which file a path names, for comparison: its device and inode when it exists; for a file
// still to be written, its folder's device and inode and its name (so "x" and "./x" agree);
// failing that, the path made absolute and normal.
std::string file_identity(const std::string& path) {
  struct stat s {};
  if (::stat(path.c_str(), &s) == 0)
    return "inode " + std::to_string(s.st_dev) + ":" + std::to_string(s.st_ino);
  const std::filesystem::path p(path);
  std::string folder = p.parent_path().string();
  if (folder.empty()) folder = ".";
  if (::stat(folder.c_str(), &s) == 0)
    return "entry " + std::to_string(s.st_dev) + ":" + std::to_string(s.st_ino) + "/" + p.filename().string();
  std::error_code ec;
  return "path " + std::filesystem::absolute(p, ec).lexically_normal().string();
}

bool names_a_file(const std::string& path) {
  struct stat s {};
  return ::stat(path.c_str(), &s) == 0;
}

}  // namespace

FileRoles& FileRoles::reads(const std::string& path) {
  if (!path.empty()) inputs_.push_back(path);
  return *this;
}

FileRoles& FileRoles::reads_pslg(const std::string& path) {
  reads(path);
  if (path.ends_with(".poly")) reads(strip_extension(path) + ".node");
  return *this;
}

FileRoles& FileRoles::reads_mesh(const std::string& prefix) {
  if (prefix.empty()) return *this;
  for (const std::string& file : io::mesh_prefix_files(prefix, io::MeshPrefixFiles::read)) reads(file);
  return *this;
}

FileRoles& FileRoles::add_output(const std::string& option, const std::string& value, const std::string& path,
                                 const std::string& noun) {
  outputs_.push_back({option, value, path, noun, groups_});
  return *this;
}

FileRoles& FileRoles::writes(const std::string& option, const std::string& path, const std::string& noun) {
  if (path.empty()) return *this;
  add_output(option, path, path, noun);
  ++groups_;
  return *this;
}

FileRoles& FileRoles::writes_mesh(const std::string& option, const std::string& prefix, const std::string& given) {
  if (prefix.empty()) return *this;
  for (const std::string& file : io::mesh_prefix_files(prefix, io::MeshPrefixFiles::written))
    add_output(option, given.empty() ? prefix : given, file, "output prefix");
  ++groups_;
  return *this;
}

FileRoles& FileRoles::writes_log(const std::string& option, const std::string& path) {
  if (path.empty()) return *this;
  add_output(option, path, path, "log");
  add_output(option, path, path + ".partial", "log");
  ++groups_;
  return *this;
}

FileRoles& FileRoles::writes_existing(const std::string& option, const std::string& value,
                                      const std::vector<std::string>& paths, const std::string& noun) {
  for (const std::string& path : paths) add_output(option, value, path, noun);
  ++groups_;
  return *this;
}

std::optional<std::string> FileRoles::clash() const {
  const auto named = [](const Output& o) {
    return (o.option.empty() ? "the default output " : o.option + " ") + o.value;
  };
  std::vector<std::string> input_ids;
  for (const std::string& input : inputs_) input_ids.push_back(names_a_file(input) ? file_identity(input) : std::string());
  std::vector<std::string> output_ids;
  for (const Output& o : outputs_) output_ids.push_back(file_identity(o.path));

  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    const Output& o = outputs_[i];
    for (std::size_t k = 0; k < inputs_.size(); ++k) {
      if (input_ids[k].empty() || input_ids[k] != output_ids[i]) continue;
      const std::string alias = o.path == inputs_[k] ? "" : " (" + o.path + " is that file by another name)";
      return named(o) + " would overwrite the input " + inputs_[k] + alias + "; choose another " + o.noun;
    }
  }
  for (std::size_t i = 0; i < outputs_.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      const Output &a = outputs_[j], &b = outputs_[i];
      if (a.group == b.group || output_ids[i] != output_ids[j]) continue;
      return named(a) + " and " + named(b) + " would write the same file (" + a.path +
             (a.path == b.path ? "" : " and " + b.path + " are one file") + "); choose another " + b.noun;
    }
  return std::nullopt;
}

}  // namespace meshstep::app
