// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/output_transaction.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <mutex>

namespace morphreg
{
namespace
{
namespace fs = std::filesystem;

/** The open transactions, in the order opened (the innermost last), and the lock guarding them and their files. */
std::mutex registry_mutex;
std::vector<OutputTransaction*> open_transactions;

std::string
normalised (const std::string& path)
{
  std::error_code ec;
  return fs::absolute (path, ec).lexically_normal ().string ();
}

/** True if \a path lies inside \a folder (at any depth). */
bool
inside (const std::string& path, const std::string& folder)
{
  const fs::path relative = fs::path (path).lexically_relative (folder);
  return !relative.empty () && *relative.begin () != ".." && relative != ".";
}

/** Creates \a folder and its missing parents; returns the outermost one created ("" if it existed). */
std::string
createFolder (const std::string& folder)
{
  fs::path outermost = folder;
  std::error_code ec;
  if (fs::is_directory (folder, ec))
    return "";
  while (outermost.has_parent_path () && outermost.parent_path () != outermost &&
         !fs::exists (outermost.parent_path (), ec))
    outermost = outermost.parent_path ();
  for (const fs::path& existing : {outermost, outermost.parent_path ()})
    if (fs::exists (existing, ec) && !fs::is_directory (existing, ec))
      throw IoError (existing.string () + ": exists and is not a folder; give a folder for the output");
  fs::create_directories (folder, ec);
  if (ec)
    throw IoError (folder + ": cannot create the output folder (" + ec.message () + ")");
  return outermost.string ();
}
} // namespace

OutputTransaction::OutputTransaction (const std::vector<std::string>& files, const std::vector<std::string>& folders)
{
  for (const std::string& file : files)
    if (!file.empty ())
      files_.push_back (normalised (file));
  for (const std::string& folder : folders) {
    folders_.push_back (normalised (folder));
    const std::string created = createFolder (folders_.back ());
    if (!created.empty ())
      created_.push_back (created);
  }
  const std::lock_guard<std::mutex> lock (registry_mutex);
  open_transactions.push_back (this);
}

OutputTransaction::~OutputTransaction ()
{
  if (!open_)
    return;
  release ();
  for (const std::string& path : written_)
    std::remove (partialPath (path).c_str ());
  std::error_code ec;
  for (const std::string& folder : created_)
    fs::remove_all (folder, ec);
}

void
OutputTransaction::release ()
{
  const std::lock_guard<std::mutex> lock (registry_mutex);
  open_transactions.erase (std::remove (open_transactions.begin (), open_transactions.end (), this),
                           open_transactions.end ());
  open_ = false;
}

bool
OutputTransaction::stage (const std::string& path)
{
  const std::string file = normalised (path);
  const std::lock_guard<std::mutex> lock (registry_mutex);
  for (auto it = open_transactions.rbegin (); it != open_transactions.rend (); ++it) {
    OutputTransaction& transaction = **it;
    const bool covered =
        std::find (transaction.files_.begin (), transaction.files_.end (), file) != transaction.files_.end () ||
        std::any_of (transaction.folders_.begin (), transaction.folders_.end (),
                     [&file] (const std::string& folder) { return inside (file, folder); });
    if (!covered)
      continue;
    if (std::find (transaction.written_.begin (), transaction.written_.end (), file) == transaction.written_.end ())
      transaction.written_.push_back (file);
    return true;
  }
  return false;
}

void
OutputTransaction::commit (const std::string& last)
{
  release ();
  std::vector<std::string> order = written_;
  const std::string final_file = last.empty () ? std::string () : normalised (last);
  const auto last_at = std::find (order.begin (), order.end (), final_file);
  if (last_at != order.end ()) {
    std::rotate (last_at, last_at + 1, order.end ());
    std::remove (final_file.c_str ()); // until it moves, the folder holds no manifest: it is not complete
  }
  for (std::size_t k = 0; k < order.size (); ++k) {
    try {
      if (!stage (order[k])) // an enclosing transaction covers it: it stays staged for that one
        commitPartial (partialPath (order[k]), order[k]);
    }
    catch (const Error&) {
      for (std::size_t rest = k; rest < order.size (); ++rest)
        std::remove (partialPath (order[rest]).c_str ());
      throw;
    }
  }
}

} // namespace morphreg
