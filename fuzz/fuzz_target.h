// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file fuzz_target.h
 *  \brief The fuzz targets: each feeds one input, written to a temporary file with the extension its loaders
 *  expect (they take paths), to the public loaders of one format. A loader may succeed or throw morphreg::Error;
 *  any other exception, a crash or a sanitizer report is a finding.
 *
 *  The same target sources build the libFuzzer executables (fuzz/CMakeLists.txt, with libfuzzer_entry.cpp) and the
 *  normal suite's replay of the committed corpora and crash reproducers (test/fuzz).
 */
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace morphreg
{
namespace fuzz
{
/** \brief One loader called on the input file. */
using Loader = std::function<void (const std::string& path)>;

/** \brief A fuzz target: its name (the folder of its corpus, fuzz/corpus/<name>/), the extension of its input files
 *  and the loaders each input goes through.
 */
struct Target
{
  std::string name;            ///< e.g. "npy"
  std::string extension;       ///< with the dot, e.g. ".npy"
  std::vector<Loader> loaders; ///< each called on every input
};

/** \brief Adds a target to targets(); called from a static initialiser in each target's source.
 *  \param[in] target the target
 *  \return true
 */
bool
registerTarget (Target target);

/** \brief Every registered target, in registration order.
 *  \return the targets
 */
const std::vector<Target>&
targets ();

/** \brief The registered target called \a name; std::invalid_argument if there is none.
 *  \param[in] name the target's name
 *  \return the target
 */
const Target&
findTarget (const std::string& name);

/** \brief Writes \a size bytes at \a data to a temporary file with the target's extension, calls each loader on it
 *  (a morphreg::Error is an accepted outcome, anything else propagates) and removes the file.
 *  \param[in] target the target
 *  \param[in] data the input
 *  \param[in] size its length in bytes
 */
void
runTarget (const Target& target, const std::uint8_t* data, std::size_t size);
} // namespace fuzz
} // namespace morphreg
