#pragma once

namespace meshstep::render {

// Under AddressSanitizer, LeakSanitizer's check at a program's exit stops every thread with
// ptrace, and its tracer died ("Tracer caught signal 11", a fatal error of its own, not a
// leak) in programs that had drawn with Mesa's software rasterizer, whose threads were still
// winding down: seen in CI on `export --tour` and on a 3D terrain export, only under load.
// A program that opts in here runs the leak check when it makes its first GL context instead,
// while no GL thread exists yet; the check then does not run again at exit. Memory errors are
// still caught all the way. A program that never draws is checked at exit as before. Nothing
// happens in other builds.
//
// The command-line programs opt in; test programs that draw in-process do not (their leaks in
// the drawing code are checked at exit).
void check_leaks_before_gl_in_this_program();

// Called by every GL context's constructor.
void check_leaks_now_if_gl_comes_next();

}  // namespace meshstep::render
