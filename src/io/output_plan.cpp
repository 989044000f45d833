// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/output_plan.h>

#include <sys/stat.h>

#include <filesystem>
#include <map>
#include <utility>

namespace morphreg
{
namespace
{
namespace fs = std::filesystem;

/** What identifies a file: its device and inode when it exists (a hard link or symbolic link to it shares them),
 *  and its absolute path with symbolic links resolved as far as they exist. */
struct FileIdentity
{
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  fs::path canonical;
};

FileIdentity
identify (const std::string& path)
{
  FileIdentity identity;
  struct stat status;
  if (::stat (path.c_str (), &status) == 0) {
    identity.exists = true;
    identity.device = status.st_dev;
    identity.inode = status.st_ino;
  }
  std::error_code ec;
  identity.canonical = fs::weakly_canonical (fs::absolute (path, ec), ec);
  if (ec)
    identity.canonical = fs::absolute (path, ec).lexically_normal ();
  return identity;
}

/** Files looked up by identity: by resolved path, and by device and inode for those that exist. */
template <typename Entry>
class FileIndex
{
public:
  explicit FileIndex (const std::vector<Entry>& entries)
  {
    for (const Entry& entry : entries) {
      const FileIdentity identity = identify (entry.path);
      by_path_.emplace (identity.canonical, &entry);
      if (identity.exists)
        by_inode_.emplace (std::make_pair (identity.device, identity.inode), &entry);
    }
  }

  /** The entry that is the same file as \a identity, or nullptr. */
  const Entry*
  find (const FileIdentity& identity) const
  {
    if (identity.exists) {
      const auto found = by_inode_.find (std::make_pair (identity.device, identity.inode));
      return found == by_inode_.end () ? nullptr : found->second;
    }
    const auto found = by_path_.find (identity.canonical);
    return found == by_path_.end () ? nullptr : found->second;
  }

private:
  std::map<fs::path, const Entry*> by_path_;
  std::map<std::pair<dev_t, ino_t>, const Entry*> by_inode_;
};

/** "path (role)", or the path alone without a role. */
std::string
described (const std::string& path, const std::string& role)
{
  return role.empty () ? path : path + " (" + role + ")";
}

/** The folder \a path lies in ("." for a bare name). */
std::string
folderOf (const std::string& path)
{
  const fs::path parent = fs::path (path).parent_path ();
  return parent.empty () ? std::string (".") : parent.string ();
}
} // namespace

void
OutputPlan::addInput (const std::string& path, const std::string& role)
{
  if (!path.empty ())
    inputs_.push_back ({path, role});
}

void
OutputPlan::addInputFolder (const std::string& folder, const std::string& role)
{
  if (!folder.empty ())
    folders_.push_back ({folder, role});
}

void
OutputPlan::addOutput (const std::string& path, const std::string& role)
{
  outputs_.push_back ({path, role});
}

void
OutputPlan::addOptionalOutput (const std::string& path, const std::string& role)
{
  if (!path.empty ())
    addOutput (path, role);
}

std::vector<std::string>
OutputPlan::outputs () const
{
  std::vector<std::string> paths;
  for (const Entry& output : outputs_)
    paths.push_back (output.path);
  return paths;
}

void
OutputPlan::checkAgainstInputs () const
{
  const FileIndex inputs (inputs_), folders (folders_);
  for (const Entry& output : outputs_) {
    if (const Entry* folder = folders.find (identify (folderOf (output.path))))
      throw InvalidInputError (described (output.path, output.role) + ": lies in " +
                               described (folder->path, folder->role) +
                               ", a folder whose files this run reads as inputs; writing there could overwrite an "
                               "input or be read as one: choose another output folder");
    if (const Entry* input = inputs.find (identify (output.path)))
      throw InvalidInputError (described (output.path, output.role) + ": is also an input, " +
                               described (input->path, input->role) +
                               "; writing it would overwrite that input: choose another output");
  }
}

void
OutputPlan::checkAgainstOutputs () const
{
  // Each output under its resolved path and, when it exists, its device and inode: a second output on either is
  // the same file.
  std::map<fs::path, std::size_t> by_path;
  std::map<std::pair<dev_t, ino_t>, std::size_t> by_inode;
  for (std::size_t k = 0; k < outputs_.size (); ++k) {
    const FileIdentity target = identify (outputs_[k].path);
    std::size_t earlier = by_path.emplace (target.canonical, k).first->second;
    if (target.exists && earlier == k)
      earlier = by_inode.emplace (std::make_pair (target.device, target.inode), k).first->second;
    if (earlier == k)
      continue;
    const Entry& first = outputs_[earlier];
    throw InvalidInputError (outputs_[k].path + ": this run would write it twice, as " +
                             (first.role.empty () ? first.path : first.role) + " and as " +
                             (outputs_[k].role.empty () ? outputs_[k].path : outputs_[k].role) +
                             "; one would overwrite the other: choose other names");
  }
}

void
OutputPlan::check () const
{
  for (const Entry& output : outputs_) {
    if (output.path.empty ())
      throw InvalidInputError ((output.role.empty () ? std::string ("an output") : output.role) +
                               ": the output file name is empty");
    requireWritableOutput (output.path);
  }
  checkAgainstInputs ();
  checkAgainstOutputs ();
}

} // namespace morphreg
