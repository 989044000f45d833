// SPDX-License-Identifier: BSD-3-Clause
#include "option_suggestions.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <vector>

namespace morphreg
{
namespace tools
{
namespace
{
/** The edit distance (insertions, deletions, substitutions) between \a a and \a b. */
std::size_t
editDistance (const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row (b.size () + 1);
  for (std::size_t j = 0; j <= b.size (); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size (); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size (); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min ({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size ()];
}

/** "; did you mean X?" for the candidate nearest \a given, if it is at most a third of its length away. */
std::string
nearest (const std::string& given, const std::vector<std::string>& candidates)
{
  std::string best;
  std::size_t best_distance = std::max<std::size_t> (2, given.size () / 3) + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = editDistance (given, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best.empty () ? "" : "; did you mean " + best + "?";
}

/** The long names of \a app's options, with their dashes. */
std::vector<std::string>
longNames (const CLI::App& app)
{
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options ())
    for (const std::string& name : option->get_lnames ())
      names.push_back ("--" + name);
  return names;
}

/** Whether \a argument is a value that merely starts with '-' (a negative number). */
bool
isNegativeNumber (const std::string& argument)
{
  return argument.size () > 1 && argument[0] == '-' &&
         (std::isdigit (static_cast<unsigned char> (argument[1])) || argument[1] == '.');
}

/** The message for the first option of \a command (or of \a app) in argv[first..] that neither knows. */
std::string
unknownOption (CLI::App& app, CLI::App& command, int first, int argc, char** argv)
{
  for (int i = first; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--")
      return "";
    if (argument.size () < 2 || argument[0] != '-' || isNegativeNumber (argument) ||
        (argument[1] != '-' && argument.size () > 2)) // a value, or short flags run together
      continue;
    const std::string name = argument.substr (0, argument.find ('='));
    if (command.get_option_no_throw (name) || app.get_option_no_throw (name))
      continue;
    std::vector<std::string> candidates = longNames (command);
    const std::vector<std::string> global = longNames (app);
    candidates.insert (candidates.end (), global.begin (), global.end ());
    return command.get_name () + ": unknown option " + name + nearest (name, candidates);
  }
  return "";
}
} // namespace

std::string
unknownArgumentMessage (CLI::App& app, int argc, char** argv)
{
  const std::vector<CLI::App*> commands = app.get_subcommands (std::function<bool (CLI::App*)> ());
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (!argument.empty () && argument[0] == '-')
      continue; // the global options (--verbose, --version, --help) are left to CLI11
    std::vector<std::string> names;
    for (CLI::App* command : commands) {
      if (command->check_name (argument))
        return unknownOption (app, *command, i + 1, argc, argv);
      names.push_back (command->get_name ());
    }
    return "unknown command " + argument + nearest (argument, names);
  }
  return "";
}
} // namespace tools
} // namespace morphreg
