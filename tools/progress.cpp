// SPDX-License-Identifier: BSD-3-Clause
// The CLI's progress display: redrawn on a terminal, a few separate lines in a log.
#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <iostream>

namespace morphreg
{
namespace tools
{
Progress::Progress (std::string label, int total, bool quiet)
  : Progress (std::move (label), total, quiet, std::cerr, isatty (STDERR_FILENO) != 0, std::chrono::seconds (5))
{}

Progress::Progress (std::string label, int total, bool quiet, std::ostream& out, bool redraw, Clock::duration interval)
  : label_ (std::move (label)), total_ (total), quiet_ (quiet), out_ (out), redraw_ (redraw), interval_ (interval)
{}

void
Progress::step (int done, const std::string& detail) const
{
  if (quiet_)
    return;
  if (redraw_) {
    out_ << '\r' << label_ << " [" << done << '/' << total_ << ']' << detail << "    " << std::flush;
    return;
  }
  const Clock::time_point now = Clock::now ();
  const int total = std::max (total_, 1);
  const bool new_tenth = last_line_done_ < 0 || done * 10 / total > last_line_done_ * 10 / total;
  if (!new_tenth && now - last_line_time_ < interval_)
    return;
  out_ << label_ << " [" << done << '/' << total_ << ']' << detail << '\n' << std::flush;
  last_line_done_ = done;
  last_line_time_ = now;
}

void
Progress::finish (int done) const
{
  if (quiet_)
    return;
  out_ << (redraw_ ? "\r" : "") << label_ << " [" << (done < 0 ? total_ : done) << '/' << total_ << "] done"
       << (redraw_ ? "    \n" : "\n") << std::flush;
}
} // namespace tools
} // namespace morphreg
