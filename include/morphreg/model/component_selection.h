// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file component_selection.h
 *  \brief Which PCA components of each region take part in a fit, and where they sit in the stacked
 *  coefficient vector m = (m_1, ..., m_K).
 */
#include <vector>

namespace morphreg
{
/** \brief The first counts[j] components of each region j, stacked region by region: region j's coefficients
 *  are m[offset(j) .. offset(j) + count(j)). Cheap to copy; made by MorphableModel::firstComponents().
 */
class ComponentSelection
{
public:
  /** \brief No region, no component. */
  ComponentSelection () : offsets_ (1, 0) {}

  /** \brief Selects \a counts[j] (>= 0) leading components of region j.
   *  \param[in] counts one count per region
   */
  explicit ComponentSelection (std::vector<int> counts);

  /** \brief The number of regions.
   *  \return counts ().size ()
   */
  int
  numRegions () const
  {
    return static_cast<int> (counts_.size ());
  }

  /** \brief Number of selected components of \a region.
   *  \param[in] region the region index
   *  \return its count
   */
  int
  count (int region) const
  {
    return counts_[region];
  }

  /** \brief Column of \a region's first selected component in the stacked coefficient vector.
   *  \param[in] region the region index
   *  \return the sum of the counts of the regions before it
   */
  int
  offset (int region) const
  {
    return offsets_[region];
  }

  /** \brief Length of the stacked coefficient vector (the number P of shape parameters).
   *  \return the sum of all counts
   */
  int
  total () const
  {
    return offsets_.back ();
  }

  /** \brief The selected components per region.
   *  \return one count per region
   */
  const std::vector<int>&
  counts () const
  {
    return counts_;
  }

  /** \brief Whether both select the same counts.
   *  \param[in] other the selection to compare with
   *  \return true for equal counts
   */
  bool
  operator== (const ComponentSelection& other) const

  {
    return counts_ == other.counts_;
  }

private:
  std::vector<int> counts_;
  std::vector<int> offsets_;
};

} // namespace morphreg
