// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Shared by the samples: "--name value" options and flags over defaults, positional arguments, and a main() wrapper
// that turns a bad argument into the usage text with exit code 2 and any other error into its message with exit 1.
#include <cmath>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace samples
{
/** A command-line mistake (unknown option, missing or malformed value): main() prints the usage. */
struct UsageError : std::invalid_argument
{
  using std::invalid_argument::invalid_argument;
};

class Options
{
public:
  /** \a defaults lists every "--name" that takes a value, \a flags every "--name" that takes none. */
  Options (int argc, char** argv, std::map<std::string, std::string> defaults, std::set<std::string> flags = {})
    : values_ (std::move (defaults))
  {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg.rfind ("--", 0) != 0)
        positional_.push_back (arg);
      else if (flags.count (arg))
        set_flags_.insert (arg);
      else if (!values_.count (arg))
        throw UsageError ("unknown option " + arg);
      else if (i + 1 == argc)
        throw UsageError (arg + " needs a value");
      else
        values_[arg] = argv[++i];
    }
  }

  const std::string&
  text (const std::string& name) const
  {
    return values_.at (name);
  }

  /** The value of \a name as a number; throws UsageError if it is not one. */
  double
  number (const std::string& name) const
  {
    const std::string& value = values_.at (name);
    char* end = nullptr;
    const double parsed = std::strtod (value.c_str (), &end);
    if (value.empty () || *end != '\0')
      throw UsageError (name + " expects a number, got '" + value + "'");
    return parsed;
  }

  /** The value of \a name as a whole number of at least \a minimum; throws UsageError otherwise. */
  int
  integer (const std::string& name, int minimum) const
  {
    const double value = number (name);
    if (!(value >= minimum && value <= 1e9) || value != std::floor (value))
      throw UsageError (name + " expects a whole number >= " + std::to_string (minimum) + ", got '" + text (name) +
                        "'");
    return static_cast<int> (value);
  }

  bool
  flag (const std::string& name) const
  {
    return set_flags_.count (name) > 0;
  }

  const std::vector<std::string>&
  positional () const
  {
    return positional_;
  }

private:
  std::map<std::string, std::string> values_;
  std::set<std::string> set_flags_;
  std::vector<std::string> positional_;
};

/** Runs \a body; "--help" prints \a usage. Returns the process exit code. */
inline int
run (int argc, char** argv, const std::string& usage, const std::function<void (int, char**)>& body)
{
  for (int i = 1; i < argc; ++i)
    if (std::string (argv[i]) == "--help") {
      std::cout << usage;
      return 0;
    }
  try {
    body (argc, argv);
    return 0;
  }
  catch (const UsageError& e) {
    std::cerr << argv[0] << ": " << e.what () << "\n" << usage;
    return 2;
  }
  catch (const std::exception& e) {
    std::cerr << argv[0] << ": " << e.what () << "\n";
    return 1;
  }
}
} // namespace samples
