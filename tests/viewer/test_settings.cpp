// The viewer's settings file: every field survives a save and a load, a missing file is the
// defaults, a damaged one keeps its good lines and says what was wrong where, the recent
// files list, where the file lives, and saving (atomic, creating the folder, failing cleanly).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "settings.hpp"

namespace meshstep::viewer {
namespace {

namespace fs = std::filesystem;
using scene::Layer;
using scene::LayerSet;

// A fresh folder per test, removed after it.
class ViewerSettings : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("meshstep-settings-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string p = path(name);
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  static std::string read(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  std::vector<std::string> listing(const fs::path& dir) const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  fs::path dir_;
};

// Sets (or unsets) an environment variable for one scope, then puts it back.
class EnvGuard {
 public:
  EnvGuard(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) {
      ::setenv(name, value, 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~EnvGuard() {
    if (old_) {
      ::setenv(name_.c_str(), old_->c_str(), 1);
    } else {
      ::unsetenv(name_.c_str());
    }
  }
  EnvGuard(const EnvGuard&) = delete;
  EnvGuard& operator=(const EnvGuard&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

// Every field away from its default.
Settings unusual() {
  Settings s;
  s.window_width = 1917;
  s.window_height = 1063;
  s.side_panel_width = 432.75f;
  s.ui_scale = 1.75f;
  s.explain_open = false;
  s.layers_open = false;
  s.stats_open = false;
  s.code_open = false;
  s.plots_open = true;
  s.color_by = scene::ColorBy::quality;
  s.theme = scene::Theme::dark;
  s.layers = LayerSet::all().set(Layer::labels, false).set(Layer::highlight, false).set(Layer::legend, false);
  s.speed = 0.1 + 0.2 + 12.0;  // not a short decimal: written exactly all the same
  s.unit = Unit::phase;
  s.follow = true;
  s.timeline_marks = MarkSet::none().set(Mark::rejected).set(Mark::flips).set(Mark::triangulate);
  s.view_3d = true;
  s.orbit = {-123.5, 12.25, 0.1 + 0.2};  // the scale not a short decimal either
  s.recent_files = {"/home/me/runs/square with spaces.msl",
                    " leading and trailing blanks\t",
                    "/a\nnewline, a \"quote\", a back\\slash, a tab\t and \x01 a control",
                    "\"starts with a quote",
                    "/ünïcödé/ðata.msl",
                    "relative/plain.msl"};
  return s;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

TEST_F(ViewerSettings, EveryFieldRoundTrips) {
  const Settings s = unusual();
  const Settings d;
  // So that a field the file forgot would come back as the default and be noticed.
  EXPECT_NE(s.window_width, d.window_width);
  EXPECT_NE(s.window_height, d.window_height);
  EXPECT_NE(s.side_panel_width, d.side_panel_width);
  EXPECT_NE(s.ui_scale, d.ui_scale);
  EXPECT_NE(s.explain_open, d.explain_open);
  EXPECT_NE(s.layers_open, d.layers_open);
  EXPECT_NE(s.stats_open, d.stats_open);
  EXPECT_NE(s.code_open, d.code_open);
  EXPECT_NE(s.plots_open, d.plots_open);
  EXPECT_NE(s.color_by, d.color_by);
  EXPECT_NE(s.theme, d.theme);
  EXPECT_NE(s.layers, d.layers);
  EXPECT_NE(s.speed, d.speed);
  EXPECT_NE(s.unit, d.unit);
  EXPECT_NE(s.follow, d.follow);
  EXPECT_NE(s.timeline_marks, d.timeline_marks);
  EXPECT_NE(s.view_3d, d.view_3d);
  EXPECT_NE(s.orbit.azimuth_deg, d.orbit.azimuth_deg);
  EXPECT_NE(s.orbit.elevation_deg, d.orbit.elevation_deg);
  EXPECT_NE(s.orbit.z_scale, d.orbit.z_scale);
  EXPECT_NE(s.recent_files, d.recent_files);

  const std::string p = path("viewer.ini");
  save_settings(s, p);
  std::vector<std::string> warnings;
  const Settings back = load_settings(p, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(back.window_width, s.window_width);
  EXPECT_EQ(back.window_height, s.window_height);
  EXPECT_EQ(back.side_panel_width, s.side_panel_width);
  EXPECT_EQ(back.ui_scale, s.ui_scale);
  EXPECT_EQ(back.explain_open, s.explain_open);
  EXPECT_EQ(back.layers_open, s.layers_open);
  EXPECT_EQ(back.stats_open, s.stats_open);
  EXPECT_EQ(back.code_open, s.code_open);
  EXPECT_EQ(back.plots_open, s.plots_open);
  EXPECT_EQ(back.color_by, s.color_by);
  EXPECT_EQ(back.theme, s.theme);
  EXPECT_EQ(back.layers.bits(), s.layers.bits());
  EXPECT_EQ(back.speed, s.speed);  // exactly
  EXPECT_EQ(back.unit, s.unit);
  EXPECT_EQ(back.follow, s.follow);
  EXPECT_EQ(back.timeline_marks, s.timeline_marks);
  EXPECT_EQ(back.view_3d, s.view_3d);
  EXPECT_EQ(back.orbit, s.orbit);  // exactly
  EXPECT_EQ(back.recent_files, s.recent_files);
  EXPECT_TRUE(back == s);

  // Readable: a comment first, names not numbers, plain paths as they are.
  const std::string text = read(p);
  EXPECT_TRUE(starts_with(text, "#")) << text;
  EXPECT_NE(text.find("\ncolor_by = quality\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\ntheme = dark\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nui_scale = 1.75\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nunit = phase\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nlayers = fill, edges, voronoi, overlay, segments, vertices, holes, caption\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\ntimeline_marks = rejected, flips, triangulate\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nview_3d = true\nazimuth = -123.5\nelevation = 12.25\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nrecent = /home/me/runs/square with spaces.msl\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nrecent = /ünïcödé/ðata.msl\n"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 21 + 6) << text;  // one line each

  // Saving what was loaded gives the same file.
  save_settings(back, p);
  EXPECT_EQ(read(p), text);
}

TEST_F(ViewerSettings, EachUnitThemeColouringAndLayerRoundTrips) {
  const std::string p = path("viewer.ini");
  for (const Unit unit : {Unit::event, Unit::step, Unit::phase}) {
    for (std::size_t c = 0; c < static_cast<std::size_t>(scene::ColorBy::count_); ++c) {
      Settings s;
      s.unit = unit;
      s.color_by = static_cast<scene::ColorBy>(c);
      s.theme = static_cast<scene::Theme>(c % 3);  // light, dark, high_contrast
      save_settings(s, p);
      std::vector<std::string> warnings;
      EXPECT_TRUE(load_settings(p, warnings) == s) << read(p);
      EXPECT_TRUE(warnings.empty());
    }
  }
  // No layers at all, each one alone, and the extremes of every range.
  std::vector<LayerSet> sets = {LayerSet::none(), LayerSet::all()};
  for (std::size_t i = 0; i < scene::kLayerCount; ++i) sets.push_back(LayerSet::none().set(static_cast<Layer>(i)));
  for (const LayerSet& layers : sets) {
    Settings s;
    s.layers = layers;
    s.window_width = Settings::kMinWindow;
    s.window_height = Settings::kMaxWindow;
    s.side_panel_width = Settings::kMaxSidePanel;
    s.speed = Playback::kMinSpeed;
    save_settings(s, p);
    std::vector<std::string> warnings;
    const Settings back = load_settings(p, warnings);
    EXPECT_EQ(back.layers.bits(), layers.bits()) << read(p);
    EXPECT_TRUE(back == s) << read(p);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
  }
}

TEST_F(ViewerSettings, MissingFileGivesTheDefaultsWithoutWarning) {
  std::vector<std::string> warnings;
  EXPECT_TRUE(load_settings(path("nothing-here.ini"), warnings) == Settings{});
  EXPECT_TRUE(load_settings(path("no-folder/viewer.ini"), warnings) == Settings{});
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  // Nor does loading create anything.
  EXPECT_TRUE(listing(dir_).empty());

  // An empty file, or one of comments and blank lines: the defaults, no warning.
  EXPECT_TRUE(load_settings(write("empty.ini", ""), warnings) == Settings{});
  EXPECT_TRUE(load_settings(write("comments.ini", "# just a comment\n\n   \n  # indented\n"), warnings) == Settings{});
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

TEST_F(ViewerSettings, DamagedFileKeepsTheGoodLinesAndWarnsPerProblem) {
  static const char kJunk[] = "\x7f" "ELF\x02\x01\x01\0\0\0\xff\xfe\x1b[31m";
  const std::string junk(kJunk, sizeof kJunk - 1);  // with its NULs
  const std::string p = write("viewer.ini",
                              "# meshstep viewer settings\n"        // 1
                              "window_width = 1500\n"               // 2  good
                              "this line is garbage\n"              // 3  garbage
                              "window_height = 99999\n"             // 4  out of range
                              "colour_by = angle\n"                 // 5  unknown key
                              "theme = dark\n"                      // 6  good
                              "speed = fast\n"                      // 7  bad number
                              "layers = fill, edges, sparkles\n"    // 8  unknown layer
                              "plots_open = true\n"                 // 9  good
                              + junk + "\n"                         // 10 binary junk
                              "recent = /good/one.msl\n"            // 11 good
                              "side_panel_width = 640\n");          // 12 good
  std::vector<std::string> warnings;
  const Settings s = load_settings(p, warnings);

  // The good lines.
  EXPECT_EQ(s.window_width, 1500);
  EXPECT_EQ(s.theme, scene::Theme::dark);
  EXPECT_TRUE(s.plots_open);
  EXPECT_EQ(s.recent_files, std::vector<std::string>{"/good/one.msl"});
  EXPECT_EQ(s.side_panel_width, 640.0f);
  // The damaged ones: the defaults.
  const Settings d;
  EXPECT_EQ(s.window_height, d.window_height);
  EXPECT_EQ(s.color_by, d.color_by);
  EXPECT_EQ(s.speed, d.speed);
  EXPECT_EQ(s.layers, d.layers);  // all of them, not "fill, edges"

  ASSERT_EQ(warnings.size(), 6u) << ::testing::PrintToString(warnings);
  const int lines[] = {3, 4, 5, 7, 8, 10};
  for (std::size_t i = 0; i < warnings.size(); ++i) {
    EXPECT_TRUE(starts_with(warnings[i], p + ":" + std::to_string(lines[i]) + ": ")) << warnings[i];
    EXPECT_TRUE(ends_with(warnings[i], "; using the default")) << warnings[i];
  }
  EXPECT_NE(warnings[0].find("this line is garbage"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("window_height"), std::string::npos) << warnings[1];
  EXPECT_NE(warnings[1].find("out of range"), std::string::npos) << warnings[1];
  EXPECT_NE(warnings[2].find("unknown key 'colour_by'"), std::string::npos) << warnings[2];
  EXPECT_NE(warnings[3].find("speed"), std::string::npos) << warnings[3];
  EXPECT_NE(warnings[4].find("sparkles"), std::string::npos) << warnings[4];
  // The junk is shown escaped: no terminal control bytes, no NULs, no broken UTF-8 in a warning.
  EXPECT_NE(warnings[5].find("ELF\\x02\\x01\\x01\\x00\\x00\\x00\\xff\\xfe\\x1b[31m"), std::string::npos) << warnings[5];
  for (const std::string& w : warnings)
    EXPECT_TRUE(std::none_of(w.begin(), w.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; })) << w;
}

TEST_F(ViewerSettings, EveryKindOfBadValueFallsBackToTheDefault) {
  const char* bad[] = {
      "window_width = 319",           "window_width = 8193",
      "window_width = 1e3",           "window_width = 12abc",
      "window_width = -1280",         "window_width = 99999999999999999999",
      "window_width =",               "window_height = 800.5",
      "side_panel_width = 199.9",     "side_panel_width = 1200.5",
      "side_panel_width = nan",       "side_panel_width = inf",
      "speed = 0.2",                  "speed = 1000.01",
      "speed = 1e400",                "speed = 4 per second",
      "explain_open = yes",           "plots_open = 1",
      "follow = TRUE",                "color_by = colour",
      "theme = purple",               "unit = seconds",
      "layers = fill,,edges",         "layers = Fill",
      "timeline_marks = flips, sparks", "timeline_marks = splits,,flips",
      "recent = \"unterminated",      "recent = \"bad \\q escape\"",
      "recent = \"x\" trailing",      "recent = \"\"",
      "= 12",                         "[viewer]",
      "view_3d = 3d",                 "azimuth = 180.5",
      "elevation = -90.01",           "elevation = nan",
      "z_scale = 0",                  "z_scale = 1001",
      "ui_scale = 0.5",               "ui_scale = 3.25",
      "ui_scale = 1.3",               "ui_scale = 1,5",
      "ui_scale = nan",               "ui_scale =",
      "theme = high contrast",
  };
  for (const char* line : bad) {
    const std::string p = write("viewer.ini", std::string("# header\n") + line + "\n");
    std::vector<std::string> warnings;
    EXPECT_TRUE(load_settings(p, warnings) == Settings{}) << line;
    ASSERT_EQ(warnings.size(), 1u) << line;
    EXPECT_TRUE(starts_with(warnings[0], p + ":2: ")) << warnings[0];
    EXPECT_TRUE(ends_with(warnings[0], "; using the default")) << warnings[0];
  }
  // What is near a limit but inside it is kept.
  const std::string p = write("viewer.ini",
                              "window_width = 320\r\n"  // a file edited on Windows
                              "  window_height   =   8192  \n"
                              "side_panel_width = 200\n"
                              "speed = 1000\n"
                              "unit = events\n"
                              "layers =  \n"
                              "timeline_marks =\n"
                              "azimuth = -180\n"
                              "elevation = 90\n"
                              "z_scale = 0.01\n"
                              "ui_scale = 3\n"
                              "theme = high-contrast\n"
                              "recent =   /spaced out/path.msl   \n");
  std::vector<std::string> warnings;
  const Settings s = load_settings(p, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(s.window_width, 320);
  EXPECT_EQ(s.window_height, 8192);
  EXPECT_EQ(s.side_panel_width, 200.0f);
  EXPECT_EQ(s.speed, 1000.0);
  EXPECT_EQ(s.unit, Unit::event);
  EXPECT_EQ(s.layers, LayerSet::none());
  EXPECT_EQ(s.timeline_marks, MarkSet::none());  // no marks at all is a choice too
  EXPECT_EQ(s.orbit, (Orbit{-180.0, 90.0, 0.01}));
  EXPECT_EQ(s.ui_scale, 3.0f);
  EXPECT_EQ(s.theme, scene::Theme::high_contrast);
  EXPECT_EQ(s.recent_files, std::vector<std::string>{"/spaced out/path.msl"});
}

TEST_F(ViewerSettings, AFileOfJunkGivesABoundedNumberOfWarnings) {
  std::string text;
  for (int i = 0; i < 500; ++i) text += "junk " + std::to_string(i) + "\n";
  text += "window_width = 2000\n";
  std::vector<std::string> warnings;
  const Settings s = load_settings(write("viewer.ini", text), warnings);
  EXPECT_EQ(s.window_width, 2000);
  ASSERT_EQ(warnings.size(), 21u);
  EXPECT_NE(warnings.back().find("480 more problems"), std::string::npos) << warnings.back();
}

TEST_F(ViewerSettings, AFileThatCannotBeReadGivesTheDefaultsAndOneWarning) {
  // A folder where the file should be (root reads any file, so not a permission test).
  const std::string p = path("viewer.ini");
  fs::create_directories(p);
  std::vector<std::string> warnings;
  EXPECT_TRUE(load_settings(p, warnings) == Settings{});
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(starts_with(warnings[0], p + ": cannot read")) << warnings[0];

  // Far too large to be a settings file.
  warnings.clear();
  EXPECT_TRUE(load_settings(write("huge.ini", std::string(3u << 20, '#')), warnings) == Settings{});
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(starts_with(warnings[0], path("huge.ini") + ": ")) << warnings[0];
}

TEST_F(ViewerSettings, RepeatedKeysTakeTheLastAndRecentFilesTheFirstTen) {
  std::string text = "theme = dark\ntheme = light\nspeed = 8\nspeed = 16\n";
  for (int i = 0; i < 14; ++i) text += "recent = /r/" + std::to_string(i % 12) + ".msl\n";
  std::vector<std::string> warnings;
  const Settings s = load_settings(write("viewer.ini", text), warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(s.theme, scene::Theme::light);
  EXPECT_EQ(s.speed, 16.0);
  ASSERT_EQ(s.recent_files.size(), Settings::kMaxRecent);
  for (std::size_t i = 0; i < Settings::kMaxRecent; ++i) EXPECT_EQ(s.recent_files[i], "/r/" + std::to_string(i) + ".msl");
}

TEST(ViewerSettingsRecent, AddRecentPutsFirstRemovesDuplicatesAndKeepsTen) {
  Settings s;
  s.add_recent("/a");
  s.add_recent("/b");
  s.add_recent("/c");
  EXPECT_EQ(s.recent_files, (std::vector<std::string>{"/c", "/b", "/a"}));
  s.add_recent("/a");  // again: to the front, once
  EXPECT_EQ(s.recent_files, (std::vector<std::string>{"/a", "/c", "/b"}));
  s.add_recent("/a");
  EXPECT_EQ(s.recent_files, (std::vector<std::string>{"/a", "/c", "/b"}));
  s.add_recent("");  // ignored
  EXPECT_EQ(s.recent_files, (std::vector<std::string>{"/a", "/c", "/b"}));

  for (int i = 0; i < 15; ++i) s.add_recent("/f" + std::to_string(i));
  ASSERT_EQ(s.recent_files.size(), Settings::kMaxRecent);
  for (std::size_t i = 0; i < Settings::kMaxRecent; ++i) EXPECT_EQ(s.recent_files[i], "/f" + std::to_string(14 - i));
  // One already in a full list moves to the front and nothing else drops out.
  s.add_recent("/f7");
  ASSERT_EQ(s.recent_files.size(), Settings::kMaxRecent);
  EXPECT_EQ(s.recent_files.front(), "/f7");
  EXPECT_EQ(s.recent_files[1], "/f14");
  EXPECT_EQ(s.recent_files.back(), "/f5");
  EXPECT_EQ(std::count(s.recent_files.begin(), s.recent_files.end(), "/f7"), 1);
}

TEST(ViewerSettingsPath, HonoursTheOverrideThenXdgThenHome) {
  {
    EnvGuard config("MESHSTEP_VIEWER_CONFIG", "/somewhere/else/my setup.ini");
    EnvGuard xdg("XDG_CONFIG_HOME", "/xdg");
    EnvGuard home("HOME", "/home/me");
    EXPECT_EQ(settings_path(), "/somewhere/else/my setup.ini");
  }
  {
    EnvGuard config("MESHSTEP_VIEWER_CONFIG", nullptr);
    EnvGuard xdg("XDG_CONFIG_HOME", "/xdg/");
    EnvGuard home("HOME", "/home/me");
    EXPECT_EQ(settings_path(), "/xdg/meshstep/viewer.ini");
  }
  {
    EnvGuard config("MESHSTEP_VIEWER_CONFIG", "");  // empty: as if unset
    EnvGuard xdg("XDG_CONFIG_HOME", nullptr);
    EnvGuard home("HOME", "/home/me");
    EXPECT_EQ(settings_path(), "/home/me/.config/meshstep/viewer.ini");
  }
  {
    EnvGuard config("MESHSTEP_VIEWER_CONFIG", nullptr);
    EnvGuard xdg("XDG_CONFIG_HOME", "relative/config");  // ignored, as the XDG spec says
    EnvGuard home("HOME", "/home/me");
    EXPECT_EQ(settings_path(), "/home/me/.config/meshstep/viewer.ini");
  }
  {
    EnvGuard config("MESHSTEP_VIEWER_CONFIG", nullptr);
    EnvGuard xdg("XDG_CONFIG_HOME", "");
    EnvGuard home("HOME", nullptr);
    EXPECT_EQ(settings_path(), "");
  }
}

TEST(ViewerSettingsPath, PutsTheEnvironmentBack) {
  const char* before = std::getenv("HOME");
  const std::optional<std::string> home = before ? std::optional<std::string>(before) : std::nullopt;
  {
    EnvGuard guard("HOME", "/elsewhere");
    EXPECT_STREQ(std::getenv("HOME"), "/elsewhere");
  }
  const char* after = std::getenv("HOME");
  EXPECT_EQ(after ? std::optional<std::string>(after) : std::nullopt, home);
}

TEST_F(ViewerSettings, SaveCreatesAMissingFolderAndReplacesTheOldFile) {
  const std::string p = path("config/meshstep/deeper/viewer.ini");
  Settings s;
  s.window_width = 2222;
  save_settings(s, p);
  ASSERT_TRUE(fs::is_regular_file(p));
  std::vector<std::string> warnings;
  EXPECT_EQ(load_settings(p, warnings).window_width, 2222);

  s.window_width = 3333;
  save_settings(s, p);
  EXPECT_EQ(load_settings(p, warnings).window_width, 3333);
  EXPECT_TRUE(warnings.empty());
  // Nothing left beside it.
  EXPECT_EQ(listing(fs::path(p).parent_path()), std::vector<std::string>{"viewer.ini"});

  // A bare file name, in the working folder.
  const fs::path cwd = fs::current_path();
  fs::current_path(dir_);
  save_settings(s, "bare.ini");
  fs::current_path(cwd);
  EXPECT_EQ(load_settings(path("bare.ini"), warnings).window_width, 3333);
}

TEST_F(ViewerSettings, SaveToAnUnwritablePathThrowsAndLeavesNoTemporaryFile) {
  // A folder in the file's place: the temporary file is written, the rename fails.
  const std::string p = path("viewer.ini");
  fs::create_directories(p);
  try {
    save_settings(Settings{}, p);
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_TRUE(starts_with(e.what(), p + ": ")) << e.what();
  }
  EXPECT_EQ(listing(dir_), std::vector<std::string>{"viewer.ini"});
  EXPECT_TRUE(fs::is_directory(p));
  EXPECT_TRUE(fs::is_empty(p));

  // A file where a folder should be: the folder cannot be made.
  const std::string blocker = write("blocker", "not a folder");
  const std::string q = blocker + "/meshstep/viewer.ini";
  try {
    save_settings(Settings{}, q);
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_TRUE(starts_with(e.what(), q + ": ")) << e.what();
  }
  EXPECT_EQ(read(blocker), "not a folder");

  // A folder without write permission (meaningless for root, who may write anywhere).
  if (::geteuid() != 0) {
    const fs::path locked = dir_ / "locked";
    fs::create_directories(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_THROW(save_settings(Settings{}, (locked / "viewer.ini").string()), InputError);
    fs::permissions(locked, fs::perms::owner_all);
    EXPECT_TRUE(fs::is_empty(locked));
  }

  // No path at all.
  EXPECT_THROW(save_settings(Settings{}, ""), InputError);
}

}  // namespace
}  // namespace meshstep::viewer
