// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file output_plan.h
 *  \brief Every file one run reads and writes, checked together before any work, so that no output can destroy an
 *  input or another output of the same run.
 *
 *  \code
 *  morphreg::OutputPlan plan;
 *  plan.addInput (scan, "--scan");
 *  plan.addInputFolder (scans_dir, "--scans (its scans)");
 *  plan.addOutput (out, "--out");
 *  plan.check (); // throws InvalidInputError naming both files
 *  \endcode
 */
#include <string>
#include <vector>

namespace morphreg
{
/** \brief The inputs and outputs of one run. check() refuses, naming both files and what each is:
 *  - an output that is an input: the same path, a hard link or a symbolic link to it (compared by device and inode);
 *  - an output directly inside a folder whose files the run reads (a folder of scans): the next read would take it
 *    for an input, and a same-named input would be overwritten;
 *  - two outputs on one file (e.g. the outputs of two scan ids that map to one name);
 *  - an empty output name, or one that cannot be written (its folder is missing or not writable, or it is a folder).
 */
class OutputPlan
{
public:
  /** \brief A file the run reads; empty names (optional inputs not given) are skipped.
   *  \param[in] path the file
   *  \param[in] role what it is, for messages (e.g. "--scan")
   */
  void
  addInput (const std::string& path, const std::string& role = "");

  /** \brief A folder whose files the run reads: no output may lie directly in it.
   *  \param[in] folder the folder
   *  \param[in] role what it is, for messages (e.g. "--scans")
   */
  void
  addInputFolder (const std::string& folder, const std::string& role);

  /** \brief A file the run writes.
   *  \param[in] path the file (an empty name is refused by check())
   *  \param[in] role what it is, for messages (e.g. "--out", "the fitted mesh of scan 'a'")
   */
  void
  addOutput (const std::string& path, const std::string& role);

  /** \brief addOutput() for an output that may not be asked for: an empty \a path is skipped.
   *  \param[in] path the file, or "" for none
   *  \param[in] role what it is, for messages
   */
  void
  addOptionalOutput (const std::string& path, const std::string& role);

  /** \brief Throws InvalidInputError (IoError for an output that cannot be written) for the first conflict found. */
  void
  check () const;

  /** \brief The output paths, in the order added.
   *  \return the outputs
   */
  std::vector<std::string>
  outputs () const;

private:
  struct Entry
  {
    std::string path, role;
  };

  void
  checkAgainstInputs () const;

  void
  checkAgainstOutputs () const;

  std::vector<Entry> inputs_, folders_, outputs_;
};

} // namespace morphreg
