// Getting an OpenGL context: each backend, the errors when there is none, and switching
// between contexts of different libraries in one process.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "render_test_support.hpp"

namespace meshstep::render::testing {
namespace {

using ::testing::HasSubstr;

// The message of the GlUnavailable that `make` throws (fails the test if it throws none).
template <class Make>
std::string failure_of(Make make) {
  try {
    make();
  } catch (const GlUnavailable& e) {
    return e.what();
  }
  ADD_FAILURE() << "no GlUnavailable thrown";
  return {};
}

TEST(GlContext, BackendNamesRoundTrip) {
  for (Backend b : {Backend::auto_, Backend::egl, Backend::osmesa}) EXPECT_EQ(parse_backend(name(b)), b);
  EXPECT_EQ(parse_backend("vulkan"), std::nullopt);
  EXPECT_EQ(parse_backend(""), std::nullopt);
}

TEST(GlContext, UnknownBackendNameFailsWithAMessage) {
  const std::string why = failure_of([] { make_offscreen_context("vulkan"); });
  EXPECT_THAT(why, HasSubstr("'vulkan'"));
  EXPECT_THAT(why, HasSubstr("auto, egl or osmesa"));
}

TEST(GlContext, BackendOutOfRangeFailsWithAMessage) {
  const std::string why = failure_of([] { make_offscreen_context(static_cast<Backend>(42)); });
  EXPECT_THAT(why, HasSubstr("does not exist"));
}

TEST(GlContext, MissingLibrariesAreNamedInTheMessage) {
  const std::string egl = failure_of([] { make_egl_context("libEGL-missing-for-test.so.1"); });
  EXPECT_THAT(egl, HasSubstr("EGL: "));
  EXPECT_THAT(egl, HasSubstr("libEGL-missing-for-test.so.1"));
  const std::string osmesa = failure_of([] { make_osmesa_context("libOSMesa-missing-for-test.so.8"); });
  EXPECT_THAT(osmesa, HasSubstr("OSMesa: "));
  EXPECT_THAT(osmesa, HasSubstr("libOSMesa-missing-for-test.so.8"));
  // A library that is there but is not the driver asked for.
  const std::string not_egl = failure_of([] { make_egl_context("libm.so.6"); });
  EXPECT_THAT(not_egl, HasSubstr("EGL: libm.so.6 lacks"));
}

// Sets an environment variable for the life of the object, then restores it.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedEnvironment() { old_ ? setenv(name_, old_->c_str(), 1) : unsetenv(name_); }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(GlContext, UnknownBackendInTheEnvironmentFailsWithAMessage) {
  const ScopedEnvironment env("MESHSTEP_GL", "directx");
  const std::string why = failure_of([] { make_offscreen_context(Backend::auto_); });
  EXPECT_THAT(why, HasSubstr("MESHSTEP_GL=directx"));
}

TEST(GlContext, EnvironmentChoosesTheBackend) {
  for (const auto& [value, expected] : {std::pair{"egl", "EGL"}, {"osmesa", "OSMesa"}}) {
    const ScopedEnvironment env("MESHSTEP_GL", value);
    try {
      EXPECT_STREQ(make_offscreen_context()->name(), expected);
    } catch (const GlUnavailable& e) {
      EXPECT_THAT(e.what(), HasSubstr(std::string("no OpenGL: ") + expected));  // not there: it says so
    }
  }
}

class ContextTest : public RenderTest {};

TEST_P(ContextTest, GivesOpenGL33Core) {
  EXPECT_STREQ(context_->name(), backend_label(GetParam()));
  const std::string description = context_->describe();
  EXPECT_THAT(description, HasSubstr("OpenGL "));
  EXPECT_THAT(description, ::testing::Not(HasSubstr("?")));
}

TEST_P(ContextTest, RendererSurvivesMakingTheContextCurrentAgain) {
  context_->make_current();
  const scene::Image image = draw(test_scene(), test_camera());
  EXPECT_PRED3(near, pixel(image, 93, 306), kRed, 2);
}

INSTANTIATE_TEST_SUITE_P(Backends, ContextTest, ::testing::Values(Backend::egl, Backend::osmesa),
                         [](const ::testing::TestParamInfo<Backend>& info) { return backend_label(info.param); });

}  // namespace
}  // namespace meshstep::render::testing
