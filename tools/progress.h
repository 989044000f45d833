#pragma once
// A one-line progress display on stderr for long CLI work ("generating heads [12/200]").
#include <iostream>
#include <string>

namespace morphreg
{
namespace tools
{
/** Rewrites one stderr line per step; finish() ends the line. Quiet mode prints nothing. */
class Progress
{
public:
  Progress (std::string label, int total, bool quiet = false)
    : label_ (std::move (label)), total_ (total), quiet_ (quiet)
  {}

  /** Shows \a done of the total, followed by \a detail (e.g. the current error). */
  void
  step (int done, const std::string& detail = "") const
  {
    if (!quiet_)
      std::cerr << '\r' << label_ << " [" << done << '/' << total_ << ']' << detail << "    " << std::flush;
  }

  /** Ends the line; \a done < 0 means all steps ran (work that may stop early, like ICP, passes its count). */
  void
  finish (int done = -1) const
  {
    if (!quiet_)
      std::cerr << '\r' << label_ << " [" << (done < 0 ? total_ : done) << '/' << total_ << "] done    \n";
  }

private:
  std::string label_;
  int total_;
  bool quiet_;
};
} // namespace tools
} // namespace morphreg
