// The pseudo-code of the published algorithms a recorded run follows, as short programs
// readable on a slide, and which line of which program the event under the cursor carries
// out. No GL, no ImGui: the viewer's panel draws it, the tests read it.
//
// Which program: by the phase of the event (inserting vertices: the insertion program, Lawson's
// flips or Bowyer-Watson's cavities as the log's header says; recovering segments and carving:
// segment recovery; refining: the refinement program that the log's parameters name, by its
// point selection and insertion; improving: vertex removal). Which line: by the event's type
// and reason, and, where one event type serves two lines, by the events round it in its step
// (a segment split because a vertex encroaches it, or instead of a rejected point; a bad
// triangle tested again while it is still in the mesh).
//
// The text keeps to the characters the viewer's font holds: Latin-1 and the arrows.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "meshstep/refine/refine.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"

namespace meshstep::scene {

struct PseudoCode {
  std::string title;               // "Off-center refinement (Üngör 2004/2009)"
  std::string reference;           // the paper(s), one line
  std::vector<std::string> lines;  // the pseudo-code, indented with spaces (4 a level)
};

enum class Program : std::uint8_t {
  lawson,                 // Delaunay insertion by flips
  bowyer_watson,          // Delaunay insertion by cavities
  segment_recovery,       // constrained Delaunay: segments recovered by flips, then carving
  // Delaunay refinement: Ruppert's loop, or Rivara's Lepp loop, round the lines of a point
  // selection. One program per selection, written by the selection's registry record
  // (refine/registry.hpp: SelectionProgram): pseudocode(Selection, Insertion).
  delaunay_refinement,
  lepp_bisection,         // Rivara's Lepp longest-edge bisection
  vertex_removal,         // improvement: removal of Steiner vertices
  lepp_surface,           // terrain: Coll, Guerrieri, Rivara, Sellarès's Lepp-surface
  greedy_terrain,         // terrain: Garland and Heckbert's greedy insertion
  count_
};

// How a Delaunay refinement program puts its points in: its last lines say so. The other
// programs have one text whatever this says.
enum class Insertion : std::uint8_t { flips, cavity };

// A program other than delaunay_refinement (which gives the circumcenter selection's).
const PseudoCode& pseudocode(Program program, Insertion insertion = Insertion::flips);
// The Delaunay refinement program of a point selection.
const PseudoCode& pseudocode(Selection selection, Insertion insertion = Insertion::flips);
// Every text there is (the refinement programs once per insertion), for a list or the tests.
std::vector<const PseudoCode*> all_pseudocode();

// What the panel shows at an event: the program, and the lines it highlights,
// [line, line + lines); line -1 when no line fits (a phase's end, an event the program has
// no line for).
struct CodeAt {
  const PseudoCode* code = nullptr;
  int line = -1;
  int lines = 0;
  Program program = Program::lawson;
  Selection selection = Selection::circumcenter;  // which one, for delaunay_refinement
};

// At the event `position` - 1 of the log (the one a cursor at `position` applied last); at
// position 0, the program of the run's first phase with no line. Reads a few events round it
// (its step's first ones, the step before): spans of events the caller got from the log
// before may go stale, as after any LogReader::event call.
CodeAt pseudocode_at(const replay::LogReader& log, std::uint64_t position);
// At the cursor's last event.
CodeAt pseudocode_at(const replay::LogReader& log, const replay::Replay& cursor);

}  // namespace meshstep::scene
