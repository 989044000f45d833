// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file memory_budget.h
 *  \brief Memory before allocation: a request whose size comes from an option or a file header (samples, an image
 *  size, a grid, a point count) is estimated first and refused with the estimate when the machine cannot hold it,
 *  instead of ending in std::bad_alloc or the out-of-memory killer.
 */
#include <cstdint>
#include <string>

namespace morphreg
{
/** \brief The memory this process may use: the machine's physical memory, or its control group's limit (a container,
 *  a Slurm job) when that is lower.
 *  \return bytes
 */
std::uint64_t
usableMemoryBytes ();

/** \brief \a bytes as a short human-readable size ("27.4 GB", "512 MB").
 *  \param[in] bytes a size
 *  \return the text
 */
std::string
memoryText (double bytes);

/** \brief Throws InvalidInputError "<what> needs about X of memory; this machine has Y" when \a bytes is more than
 *  usableMemoryBytes().
 *  \param[in] bytes the estimate of what the request allocates
 *  \param[in] what the request, naming the option or file it comes from (e.g. "--samples 100000 of the ICT model")
 */
void
requireMemory (double bytes, const std::string& what);

} // namespace morphreg
