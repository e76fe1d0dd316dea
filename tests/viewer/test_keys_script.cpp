// The key table and the script reader.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "keys.hpp"
#include "meshstep/error.hpp"
#include "script.hpp"

namespace meshstep::viewer {
namespace {

TEST(ViewerKeys, ParsesChordsAsScriptsWriteThem) {
  EXPECT_EQ(parse_chord("Space"), (Chord{GLFW_KEY_SPACE}));
  EXPECT_EQ(parse_chord("shift+right"), (Chord{GLFW_KEY_RIGHT, true}));
  EXPECT_EQ(parse_chord("Ctrl+3"), (Chord{GLFW_KEY_3, false, true}));
  EXPECT_EQ(parse_chord("Shift+Ctrl+S"), (Chord{GLFW_KEY_S, true, true}));
  EXPECT_EQ(parse_chord("F11"), (Chord{GLFW_KEY_F11}));
  EXPECT_EQ(parse_chord("?"), (Chord{GLFW_KEY_SLASH, true}));
  EXPECT_EQ(parse_chord("+"), (Chord{GLFW_KEY_EQUAL, true}));  // as a keyboard types it
  EXPECT_EQ(parse_chord("="), (Chord{GLFW_KEY_EQUAL}));
  EXPECT_EQ(parse_chord("kp+"), (Chord{GLFW_KEY_KP_ADD}));
  EXPECT_FALSE(parse_chord("F13"));
  EXPECT_FALSE(parse_chord("Hyper+X"));
  EXPECT_FALSE(parse_chord(""));
}

TEST(ViewerKeys, EveryChordDoesOneThingAndSaysWhat) {
  std::set<std::tuple<int, bool, bool>> seen;
  for (const KeyAction& a : key_actions()) {
    EXPECT_TRUE(seen.insert({a.chord.key, a.chord.shift, a.chord.ctrl}).second) << a.keys << " is bound twice";
    EXPECT_TRUE(a.run) << a.keys;
    // The help text names the key as scripts press it.
    EXPECT_EQ(parse_chord(a.keys), a.chord) << a.keys;
  }
  EXPECT_GE(seen.size(), 40u);
}

class ScriptFile : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    path_ = (std::filesystem::temp_directory_path() / ("viewer_script_" + std::to_string(::getpid()) + ".txt")).string();
    std::ofstream(path_) << text;
    return path_;
  }
  void TearDown() override { std::filesystem::remove(path_); }
  std::string path_;
};

TEST_F(ScriptFile, ReadsActionsSkippingCommentsAndBlankLines) {
  const auto actions = read_script(write("# a tour\n\nseek step 4   # to the fourth\nkey Shift+Right\nplay 30\nquit\n"));
  ASSERT_EQ(actions.size(), 4u);
  EXPECT_EQ(actions[0].verb, "seek");
  EXPECT_EQ(actions[0].args, (std::vector<std::string>{"step", "4"}));
  EXPECT_EQ(actions[0].line, 3);
  EXPECT_EQ(actions[3].verb, "quit");
  // The 3D view's actions.
  const auto view = read_script(write("view 3d\norbit -60.5 -90\nz-scale 2.5\nview 2d\n"));
  ASSERT_EQ(view.size(), 4u);
  EXPECT_EQ(view[1].args, (std::vector<std::string>{"-60.5", "-90"}));
  EXPECT_EQ(view[2].verb, "z-scale");
}

TEST_F(ScriptFile, NamesTheFileAndLineOfAMistake) {
  const struct {
    const char* text;
    const char* message;
  } cases[] = {
      {"frames 2\nbogus\n", ":2: unknown action 'bogus'"},
      {"seek step x\n", ":1: expected: seek step N"},
      {"key Hyper+Q\n", ":1: unknown key 'Hyper+Q'"},
      {"toggle walls\n", ":1: unknown layer 'walls'"},
      {"color-by taste\n", ":1: unknown colouring 'taste'"},
      {"\n\nplay\n", ":3: expected: play N"},
      {"screenshot\n", ":1: expected: screenshot FILE"},
      {"drag 1\n", ":1: expected: drag X Y"},
      {"view 4d\n", ":1: expected: view 2d|3d"},
      {"orbit -60 95\n", ":1: expected: orbit AZ EL (degrees, the elevation from -90 to 90)"},
      {"orbit -60\n", ":1: expected: orbit AZ EL"},
      {"z-scale 0\n", ":1: expected: z-scale K (a number > 0)"},
  };
  for (const auto& c : cases) {
    try {
      read_script(write(c.text));
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path_ + c.message), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(read_script("/nonexistent/script.txt"), InputError);
}

}  // namespace
}  // namespace meshstep::viewer
