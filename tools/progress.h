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

  void
  step (int done) const
  {
    if (!quiet_)
      std::cerr << '\r' << label_ << " [" << done << '/' << total_ << ']' << std::flush;
  }

  void
  finish () const
  {
    if (!quiet_)
      std::cerr << '\r' << label_ << " [" << total_ << '/' << total_ << "] done\n";
  }

private:
  std::string label_;
  int total_;
  bool quiet_;
};
} // namespace tools
} // namespace morphreg
