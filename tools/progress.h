// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A progress display on stderr for long CLI work ("generating heads [12/200]"): one line redrawn in place on a
// terminal; in a log, separate lines and only a few of them.
#include <chrono>
#include <ostream>
#include <string>

namespace morphreg
{
namespace tools
{
/** Shows the steps of one stage; finish() ends it. Quiet mode prints nothing. On a terminal each step rewrites the
 *  line with '\r'; elsewhere (a log, a pipe) a step writes a line of its own only when it is the first, starts a new
 *  tenth of the total or comes an interval after the last line, and finish() writes the last line.
 */
class Progress
{
public:
  using Clock = std::chrono::steady_clock;

  /** Progress on stderr, redrawn in place when stderr is a terminal; in a log at most a line per tenth or 5 s. */
  Progress (std::string label, int total, bool quiet = false);

  /** Progress on \a out; \a redraw rewrites one line with '\r', otherwise a line is written at most per tenth of
   *  \a total or per \a interval.
   */
  Progress (std::string label, int total, bool quiet, std::ostream& out, bool redraw, Clock::duration interval);

  /** Shows \a done of the total, followed by \a detail (e.g. the current error). */
  void
  step (int done, const std::string& detail = "") const;

  /** Ends the stage; \a done < 0 means all steps ran (work that may stop early, like ICP, passes its count). */
  void
  finish (int done = -1) const;

private:
  std::string label_;
  int total_;
  bool quiet_;
  std::ostream& out_;
  bool redraw_;
  Clock::duration interval_;
  mutable int last_line_done_ = -1; ///< the step of the last line written when not redrawing; -1 before the first
  mutable Clock::time_point last_line_time_;
};
} // namespace tools
} // namespace morphreg
