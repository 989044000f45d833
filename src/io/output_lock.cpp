// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/io/output_lock.h>

#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/json_file.h>

#include <nlohmann/json.hpp>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace morphreg
{
namespace
{
namespace fs = std::filesystem;

/** The lock file this process holds (empty: none), for releaseOutputLockNow() in a signal handler. */
char held_lock[4096] = {};

std::string
hostName ()
{
  char name[256] = {};
  if (gethostname (name, sizeof (name) - 1) != 0)
    return "unknown";
  return name;
}

/** Field 22 of /proc/<pid>/stat, the process's start time in clock ticks since boot; "" for a zombie (dead, not yet
 *  reaped); nullopt if /proc has no such process (or there is no /proc). */
std::optional<std::string>
processStart (long pid)
{
  std::ifstream stat ("/proc/" + std::to_string (pid) + "/stat");
  std::string text;
  std::getline (stat, text);
  const std::size_t name_end = text.rfind (')');
  if (name_end == std::string::npos)
    return std::nullopt;
  std::istringstream fields (text.substr (name_end + 1));
  std::string value, state;
  fields >> state;
  for (int field = 4; field <= 22; ++field)
    if (!(fields >> value))
      return std::nullopt;
  return state == "Z" ? "" : value;
}

enum class Liveness
{
  alive,
  gone,
  unknown
};

/** Whether the owner's process still runs: known only on its own host. */
Liveness
liveness (const LockOwner& owner)
{
  if (owner.host != hostName ())
    return Liveness::unknown;
  const std::optional<std::string> start = processStart (owner.pid);
  if (!start)
    return ::kill (static_cast<pid_t> (owner.pid), 0) != 0 && errno == ESRCH ? Liveness::gone : Liveness::alive;
  if (start->empty ())
    return Liveness::gone; // a zombie
  return owner.process_start.empty () || *start == owner.process_start ? Liveness::alive : Liveness::gone;
}

std::string
utcNow ()
{
  const std::time_t now = std::time (nullptr);
  std::tm utc{};
  gmtime_r (&now, &utc);
  char text[32];
  std::strftime (text, sizeof (text), "%Y-%m-%d %H:%M:%S UTC", &utc);
  return text;
}

nlohmann::json
ownerJson (const LockOwner& owner)
{
  return {{"pid", owner.pid},         {"host", owner.host}, {"process_start", owner.process_start},
          {"started", owner.started}, {"run", owner.run},   {"shards", owner.shards}};
}

/** The owner recorded in the lock file \a path; nullopt if it has gone meanwhile (its run ended). */
std::optional<LockOwner>
readLock (const std::string& path)
{
  std::error_code ec;
  if (!fs::exists (path, ec))
    return std::nullopt;
  try {
    const nlohmann::json lock = readJsonFile (path);
    if (lock.at ("pid").get<long> () <= 0)
      throw FormatError (path + ": no process id");
    return LockOwner{lock.at ("pid").get<long> (),
                     lock.at ("host").get<std::string> (),
                     lock.at ("process_start").get<std::string> (),
                     lock.at ("started").get<std::string> (),
                     lock.at ("run").get<std::string> (),
                     lock.at ("shards").get<int> ()};
  }
  catch (const std::exception&) {
    if (!fs::exists (path, ec))
      return std::nullopt;
    throw IoError (path + ": not a lock file morphreg can read; if no morphreg run is using its folder, delete it");
  }
}

/** Creates \a path holding \a content if it does not exist, atomically (a complete file or none); false if it
 *  exists. */
bool
createLock (const std::string& path, const std::string& content)
{
  const std::string temporary = path + "." + std::to_string (getpid ()) + ".tmp";
  writeFileAtomically (temporary, content);
  const int linked = ::link (temporary.c_str (), path.c_str ());
  const int error = errno;
  std::remove (temporary.c_str ());
  if (linked == 0)
    return true;
  if (error == EEXIST)
    return false;
  throw IoError (path + ": cannot create the lock file (" + std::strerror (error) + ")");
}

/** The refusal of a live (or, on another host, possibly live) lock \a path of \a owner, with \a why. */
std::string
refusal (const std::string& path, const LockOwner& owner, Liveness state, const std::string& why)
{
  return path + ": " + why + "; it is held by " + owner.text () +
         (state == Liveness::unknown ? " (another machine: whether it still runs cannot be checked from here)"
                                     : " (still running)") +
         ". Wait for that run to end or, if it no longer runs, delete the lock file";
}

/** Takes the lock file \a path for \a self; a stale one is taken over, saying so on \a out. */
void
takeLock (const std::string& path, const LockOwner& self, std::ostream& out)
{
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (createLock (path, ownerJson (self).dump (2) + "\n"))
      return;
    const std::optional<LockOwner> owner = readLock (path);
    if (!owner)
      continue; // released meanwhile
    const Liveness state = liveness (*owner);
    if (state != Liveness::gone)
      throw IoError (refusal (path, *owner, state, "another run is registering the same scans into this folder"));
    out << "register: " << path << ": taking over the stale lock of " << owner->text ()
        << ": that process no longer runs" << std::endl;
    std::remove (path.c_str ());
  }
  throw IoError (path + ": another run took the lock at the same moment; try again");
}

/** IoError if a live lock of \a out_dir other than \a own belongs to a run that is not another shard of \a self's
 *  study: their outputs could overwrite each other. */
void
refuseUnrelatedRuns (const std::string& out_dir, const std::string& own, const LockOwner& self)
{
  static const std::regex name ("\\.morphreg(\\.shard-[0-9]+-of-[0-9]+)?\\.lock");
  for (const auto& item : fs::directory_iterator (out_dir)) {
    const std::string path = item.path ().string ();
    if (path == own || !std::regex_match (item.path ().filename ().string (), name))
      continue;
    const std::optional<LockOwner> owner = readLock (path);
    if (!owner || (self.shards > 1 && owner->shards == self.shards && owner->run == self.run))
      continue; // gone, or another shard of the same job array
    const Liveness state = liveness (*owner);
    if (state != Liveness::gone)
      throw IoError (refusal (path, *owner, state,
                              "another run (another study, model, settings or shard count) is writing to " + out_dir));
  }
}

std::string
lockPath (const std::string& out_dir, int shard, int shards)
{
  const std::string name =
      shards > 1 ? ".morphreg.shard-" + std::to_string (shard) + "-of-" + std::to_string (shards) + ".lock"
                 : std::string (".morphreg.lock");
  return (fs::path (out_dir) / name).string ();
}
} // namespace

std::string
LockOwner::text () const
{
  return "pid " + std::to_string (pid) + " on host " + host + ", since " + started;
}

OutputLock::OutputLock (const std::string& out_dir, int shard, int shards, const std::string& run, std::ostream& out)
  : path_ (lockPath (out_dir, shard, shards))
{
  const long pid = static_cast<long> (getpid ());
  const LockOwner self{pid, hostName (), processStart (pid).value_or (""), utcNow (), run, shards};
  takeLock (path_, self, out);
  std::snprintf (held_lock, sizeof (held_lock), "%s", path_.c_str ());
  try {
    refuseUnrelatedRuns (out_dir, path_, self);
  }
  catch (...) {
    releaseOutputLockNow ();
    throw;
  }
}

OutputLock::~OutputLock ()
{
  releaseOutputLockNow ();
}

void
releaseOutputLockNow ()
{
  if (held_lock[0] != '\0')
    ::unlink (held_lock);
  held_lock[0] = '\0';
}
} // namespace morphreg
