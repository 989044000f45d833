// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file output_transaction.h
 *  \brief The outputs of one run committed together: whole, or not at all, with the old ones kept on failure.
 *
 *  While a transaction is open, every file morphreg writes (writeAtomically(), atomic_file.h) to one of its paths,
 *  or anywhere inside one of its folders, is written under its temporary name (partialPath()) and left there.
 *  commit() renames them all into place; a transaction destroyed without commit() removes them, so a run that fails
 *  half-way (a full disk, a screenshot that cannot be rendered, a bad input found late) changes no file: old
 *  outputs stay as they were, none is removed, and no partial file is left. Folders the transaction had to create
 *  are removed too.
 *
 *  Transactions nest: a file committed by an inner transaction whose path an outer one also covers stays staged
 *  for the outer one (build-model --from-scans commits each scan's outputs into its report folder, which is
 *  committed with the model).
 *
 *  \code
 *  morphreg::OutputTransaction outputs ({"fit.ply", "fit.json"});
 *  morphreg::savePolygonMesh ("fit.ply", mesh);     // written to .partial.fit.ply
 *  morphreg::writeJsonFile ("fit.json", report);    // written to .partial.fit.json
 *  outputs.commit ();                               // both renamed into place
 *  \endcode
 */
#include <string>
#include <vector>

namespace morphreg
{
/** \brief A set of output files and folders written together (see the file's description). Thread-safe: the runs
 *  of a batch open one transaction each, on different files. */
class OutputTransaction
{
public:
  /** \brief Opens a transaction on \a files and on every file written inside \a folders (created when missing, and
   *  removed again by a rollback).
   *  \param[in] files output files (empty names are skipped)
   *  \param[in] folders output folders
   */
  explicit OutputTransaction (const std::vector<std::string>& files, const std::vector<std::string>& folders = {});

  /** \brief Rolls back unless committed: removes the staged files and the folders it created. */
  ~OutputTransaction ();

  OutputTransaction (const OutputTransaction&) = delete;
  OutputTransaction&
  operator= (const OutputTransaction&) = delete;

  /** \brief Renames every file written during the transaction into place, \a last (if written) after all others:
   *  a folder's manifest, so that a folder with its manifest is complete. Throws IoError naming the file if a
   *  rename fails.
   *  \param[in] last the file to put in place last ("" for none); its old copy is removed before the others move
   */
  void
  commit (const std::string& last = "");

  /** \brief Called by writeAtomically() after writing \a path's partial file: true if an open transaction takes it
   *  (the partial file then stays until that transaction commits), false if it is to be renamed at once.
   *  \param[in] path the file just written under partialPath(path)
   *  \return whether a transaction staged it
   */
  static bool
  stage (const std::string& path);

private:
  void
  release ();

  std::vector<std::string> files_, folders_; ///< absolute, normalised
  std::vector<std::string> written_;         ///< the files staged, in the order written
  std::vector<std::string> created_;         ///< folders created by the constructor, outermost first
  bool open_ = true;
};

} // namespace morphreg
