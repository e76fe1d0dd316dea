// The file dialog: its model on a folder made for the test (what it lists and in which
// order, hidden files, into and up, a typed path, a folder that is missing or not a folder),
// the `type` script action, and the whole program: from the start page, Ctrl+O, a typed
// path and Enter open the file, and a file that cannot be opened is reported on the page.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "program_support.hpp"
#include "file_dialog.hpp"
#include "keys.hpp"
#include "meshstep/error.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "script.hpp"

namespace meshstep::viewer {
namespace {

using testing::has;
using testing::read_text;
using testing::Result;
using testing::run;

namespace fs = std::filesystem;
using Kind = FileEntry::Kind;

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

std::vector<std::string> names(const FileDialog& d) {
  std::vector<std::string> out;
  for (const FileEntry& e : d.entries()) out.push_back(e.name);
  return out;
}

// A fresh folder per test, removed after it, holding a bit of everything:
//   Alpha/ beta/ .hidden/                      folders (one hidden)
//   b.poly A.mslog c.node                      an input, a log, a lone .node (an input)
//   mesh.node + mesh.ele                       a mesh, listed as "mesh"
//   notes.txt z.ele .secret.poly               not listed (another kind; an .ele alone; hidden)
class FileDialogModel : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("meshstep-dialog-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
    for (const char* folder : {"Alpha", "beta", ".hidden"}) fs::create_directories(dir_ / folder);
    write(dir_ / "b.poly", "4 2 0 0\n");
    write(dir_ / "A.mslog", "MSTEPLOG");
    write(dir_ / "c.node", "3 2 0 0\n");
    write(dir_ / "mesh.node", std::string(1500, 'n'));
    write(dir_ / "mesh.ele", std::string(600, 'e'));
    write(dir_ / "notes.txt", "not for the viewer");
    write(dir_ / "z.ele", "an .ele without its .node");
    write(dir_ / ".secret.poly", "hidden");
    write(dir_ / "Alpha" / "inner.poly", "inside");
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(FileDialogModel, ListsFoldersThenTheFilesTheViewerOpensByName) {
  const FileDialog d(dir_.string());
  EXPECT_EQ(d.folder(), dir_.string());
  EXPECT_EQ(d.message(), "");
  // Folders first, then files, each by name ignoring case; the mesh once, by its prefix.
  EXPECT_EQ(names(d), (std::vector<std::string>{"Alpha", "beta", "A.mslog", "b.poly", "c.node", "mesh"}));
  const std::vector<FileEntry>& e = d.entries();
  ASSERT_EQ(e.size(), 6u);
  const Kind kinds[] = {Kind::folder, Kind::folder, Kind::log, Kind::input, Kind::input, Kind::mesh};
  for (std::size_t i = 0; i < e.size(); ++i) EXPECT_EQ(e[i].kind, kinds[i]) << e[i].name;
  EXPECT_EQ(e[0].path, path("Alpha"));
  EXPECT_EQ(e[3].path, path("b.poly"));
  EXPECT_EQ(e[3].bytes, 8u);
  EXPECT_EQ(e[5].path, path("mesh"));  // the PREFIX, as `meshstep view` takes a mesh
  EXPECT_EQ(e[5].bytes, 1500u + 600u);  // .node and .ele together
  EXPECT_EQ(e[0].bytes, 0u);
}

TEST_F(FileDialogModel, ShowsHiddenNamesOnlyWhenAsked) {
  FileDialog d(dir_.string());
  EXPECT_FALSE(d.show_hidden());
  d.set_show_hidden(true);
  EXPECT_EQ(names(d),
            (std::vector<std::string>{".hidden", "Alpha", "beta", ".secret.poly", "A.mslog", "b.poly", "c.node",
                                      "mesh"}));
  d.set_show_hidden(false);
  EXPECT_EQ(names(d).size(), 6u);
}

TEST_F(FileDialogModel, GoesIntoAFolderAndUpAgain) {
  FileDialog d(dir_.string());
  // A folder entry is gone into (nothing is picked); a file entry is picked.
  EXPECT_EQ(d.activate(0), std::nullopt);
  EXPECT_EQ(d.folder(), path("Alpha"));
  EXPECT_EQ(names(d), std::vector<std::string>{"inner.poly"});
  EXPECT_EQ(d.activate(0), path("Alpha/inner.poly"));
  EXPECT_TRUE(d.go_up());
  EXPECT_EQ(d.folder(), dir_.string());
  EXPECT_EQ(d.activate(5), path("mesh"));
  EXPECT_EQ(d.activate(99), std::nullopt);  // out of range: nothing
  EXPECT_EQ(d.folder(), dir_.string());
  // Relative to where it is; up to the root and no further.
  EXPECT_TRUE(d.go_to("beta"));
  EXPECT_EQ(d.folder(), path("beta"));
  EXPECT_TRUE(d.go_to("../Alpha/."));
  EXPECT_EQ(d.folder(), path("Alpha"));
  while (d.folder() != "/") ASSERT_TRUE(d.go_up()) << d.folder();
  EXPECT_FALSE(d.go_up());
  EXPECT_EQ(d.folder(), "/");
}

TEST_F(FileDialogModel, ATypedFolderIsGoneIntoAndATypedFileIsPicked) {
  FileDialog d(dir_.string());
  EXPECT_EQ(d.submit("  beta  "), std::nullopt);
  EXPECT_EQ(d.folder(), path("beta"));
  EXPECT_TRUE(d.entries().empty());
  EXPECT_EQ(d.submit("../b.poly"), path("b.poly"));        // relative to the folder shown
  EXPECT_EQ(d.submit(path("A.mslog")), path("A.mslog"));    // absolute
  EXPECT_EQ(d.submit("../mesh"), path("mesh"));             // a mesh PREFIX names no file
  EXPECT_EQ(d.submit("../notes.txt"), path("notes.txt"));   // typed: picked even if not listed
  EXPECT_EQ(d.submit(dir_.string() + "/"), std::nullopt);   // a folder, trailing slash
  EXPECT_EQ(d.folder(), dir_.string());
  EXPECT_EQ(d.message(), "");

  EXPECT_EQ(d.submit("nothing.poly"), std::nullopt);
  EXPECT_EQ(d.message(), "no such file or folder: " + path("nothing.poly"));
  EXPECT_EQ(d.folder(), dir_.string());
  EXPECT_EQ(names(d).size(), 6u);
  EXPECT_EQ(d.submit("   "), std::nullopt);
  EXPECT_EQ(d.message(), "type the path of a file or folder");
  // The next good move clears the message.
  EXPECT_EQ(d.submit("b.poly"), path("b.poly"));
  EXPECT_EQ(d.message(), "");
}

TEST_F(FileDialogModel, AMissingOrUnreadableFolderGivesAMessageAndStaysPut) {
  FileDialog d(dir_.string());
  EXPECT_FALSE(d.go_to(path("missing")));
  EXPECT_EQ(d.message(), "no such folder: " + path("missing"));
  EXPECT_EQ(d.folder(), dir_.string());
  EXPECT_EQ(names(d).size(), 6u);
  EXPECT_FALSE(d.go_to("b.poly"));
  EXPECT_EQ(d.message(), "not a folder: " + path("b.poly"));
  EXPECT_EQ(d.folder(), dir_.string());
  // Started in a folder that is gone: the current folder instead, saying why.
  const FileDialog elsewhere(path("missing/deeper"));
  EXPECT_EQ(elsewhere.folder(), fs::current_path().string());
  EXPECT_EQ(elsewhere.message(), "no such folder: " + path("missing/deeper"));
  // A folder without read permission (meaningless for root, who reads anything).
  if (::geteuid() != 0) {
    fs::permissions(dir_ / "beta", fs::perms::none);
    EXPECT_FALSE(d.go_to("beta"));
    EXPECT_EQ(d.message().rfind("cannot read " + path("beta") + ": ", 0), 0u) << d.message();
    EXPECT_EQ(d.folder(), dir_.string());
    fs::permissions(dir_ / "beta", fs::perms::owner_all);
  }
}

TEST_F(FileDialogModel, StartsInTheFolderOfTheFileOpenNowElseTheCurrentOne) {
  EXPECT_EQ(FileDialog::start_folder(path("b.poly")), dir_.string());
  EXPECT_EQ(FileDialog::start_folder(path("mesh")), dir_.string());  // a PREFIX
  EXPECT_EQ(FileDialog::start_folder(""), fs::current_path().string());
  EXPECT_EQ(FileDialog::start_folder(path("gone/run.mslog")), fs::current_path().string());
  // A relative file: its folder, made absolute.
  const fs::path cwd = fs::current_path();
  fs::current_path(dir_);
  EXPECT_EQ(FileDialog::start_folder("Alpha/inner.poly"), path("Alpha"));
  fs::current_path(cwd);
}

TEST(FileDialogSizes, AreShortAndInBinaryUnits) {
  char text[32];
  const std::pair<std::uintmax_t, const char*> cases[] = {
      {0, "0 B"},           {1023, "1023 B"},        {1024, "1.0 KiB"},
      {1536, "1.5 KiB"},    {5u << 20, "5.0 MiB"},   {3ull << 30, "3.0 GiB"}};
  for (const auto& [bytes, expected] : cases) {
    format_size(bytes, text, sizeof text);
    EXPECT_STREQ(text, expected) << bytes;
  }
}

TEST(FileDialogKeys, CtrlOOpensItAndTheHelpListsIt) {
  EXPECT_EQ(parse_chord("Ctrl+O"), open_file_chord());
  bool listed = false;
  for (const KeyAction& a : key_actions())
    listed = listed || (a.chord == open_file_chord() && a.what && std::string(a.keys) == "Ctrl+O");
  EXPECT_TRUE(listed);  // (pressing it in a viewer: FileDialogProgram.CtrlOInAViewerOpensAnotherFile)
}

TEST(FileDialogScript, TypeTakesTheRestOfTheLine) {
  const fs::path file = fs::temp_directory_path() / ("viewer_type_" + std::to_string(::getpid()) + ".txt");
  std::ofstream(file) << "type   /a folder/with  two spaces.poly   # a comment\nkey Enter\n";
  const std::vector<ScriptAction> actions = read_script(file.string());
  ASSERT_EQ(actions.size(), 2u);
  EXPECT_EQ(actions[0].verb, "type");
  EXPECT_EQ(actions[0].args, std::vector<std::string>{"/a folder/with  two spaces.poly"});
  std::ofstream(file) << "type\n";
  try {
    read_script(file.string());
    ADD_FAILURE() << "accepted a type without text";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ":1: expected: type TEXT"), std::string::npos) << e.what();
  }
  fs::remove(file);
}

// --- The program ----------------------------------------------------------------------




class FileDialogProgram : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("viewer_dialog_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  // The viewer off screen on INPUT (none: the start page), running this script.
  Result view(const std::string& script, const std::string& input = "") {
    std::ofstream(dir_ / "script.txt") << script;
    return run(std::string(MESHSTEP_VIEW_BINARY) + " " + input + " --offscreen -q --window 1280x800 --script " +
               (dir_ / "script.txt").string());
  }
  // What the viewer records for an input, recorded here the same way: `meshstep triangulate`.
  std::string record(const std::string& input, const std::string& name) {
    const std::string log = (dir_ / name).string();
    const Result r =
        run(std::string(MESHSTEP_BINARY) + " triangulate " + input + " --record " + log + " --no-output -q");
    EXPECT_EQ(r.status, 0) << r.output;
    return log;
  }
  // The state's fields that say which run is open and where, exactly.
  static void expect_open_at_end(const std::string& json, const std::string& title, const replay::LogReader& log) {
    const std::string events = std::to_string(log.event_count()), steps = std::to_string(log.step_count());
    EXPECT_FALSE(has(json, "\"page\": \"start\"")) << json;
    EXPECT_TRUE(has(json, "\n  \"title\": \"" + title + "\",\n")) << json;
    EXPECT_TRUE(has(json, "\n  \"position\": " + events + ",\n")) << json;  // opened at its end
    EXPECT_TRUE(has(json, "\n  \"event_count\": " + events + ",\n")) << json;
    EXPECT_TRUE(has(json, "\n  \"step\": " + steps + ",\n")) << json;
    EXPECT_TRUE(has(json, "\n  \"step_count\": " + steps + ",\n")) << json;
    EXPECT_TRUE(has(json, "\n  \"playing\": false,\n")) << json;
  }
  fs::path dir_;
};

#define SKIP_WITHOUT_GL(r) \
  if ((r).status != 0 && has((r).output, "cannot open a window or draw")) GTEST_SKIP() << (r).output

TEST_F(FileDialogProgram, CtrlOATypedPathAndEnterOpenTheFile) {
  const std::string input = std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly";
  const fs::path state = dir_ / "state.json";
  const Result r = view("frames 2\nkey ctrl+o\ntype " + input + "\nkey enter\nframes 2\nstate " + state.string() +
                        "\nquit\n");
  SKIP_WITHOUT_GL(r);
  ASSERT_EQ(r.status, 0) << r.output;
  const replay::LogReader log(record(input, "lesson.mslog"));
  expect_open_at_end(read_text(state), input, log);
}

// In a viewer the key goes through the key table: the dialog starts in the open log's
// folder, so a name typed alone is found there.
TEST_F(FileDialogProgram, CtrlOInAViewerOpensAnotherFile) {
  const std::string plate = std::string(MESHSTEP_ASSETS) + "/examples/plate.poly";
  const std::string first = record(std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly", "first.mslog");
  const std::string second = record(plate, "second.mslog");
  const fs::path state = dir_ / "state.json";
  const Result r = view("frames 2\nkey ctrl+o\ntype second.mslog\nkey enter\nframes 2\nstate " + state.string() +
                            "\nquit\n",
                        first);
  SKIP_WITHOUT_GL(r);
  ASSERT_EQ(r.status, 0) << r.output;
  const replay::LogReader log(second);
  expect_open_at_end(read_text(state), second, log);
}

TEST_F(FileDialogProgram, AFileThatCannotBeOpenedIsReportedOnThePage) {
  // Picked in the dialog, then refused by the opener: the page says why, as for a drop.
  const fs::path junk = dir_ / "junk.mslog";
  write(junk, "not a log at all");
  const fs::path state = dir_ / "state.json";
  const Result r = view("frames 2\nkey ctrl+o\ntype " + junk.string() + "\nkey enter\nframes 2\nstate " +
                        state.string() + "\nquit\n");
  SKIP_WITHOUT_GL(r);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string json = read_text(state);
  EXPECT_TRUE(has(json, "\"page\": \"start\"")) << json;
  EXPECT_TRUE(has(json, "\"problem\": \"" + junk.string() + ": not a replay log")) << json;
}

}  // namespace
}  // namespace meshstep::viewer
