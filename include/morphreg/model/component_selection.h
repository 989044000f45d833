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
  ComponentSelection () : offsets_ (1, 0) {}

  /** \brief Selects \a counts[j] (>= 0) leading components of region j. */
  explicit ComponentSelection (std::vector<int> counts);

  int
  numRegions () const
  {
    return static_cast<int> (counts_.size ());
  }

  /** \brief Number of selected components of \a region. */
  int
  count (int region) const
  {
    return counts_[region];
  }

  /** \brief Column of \a region's first selected component in the stacked coefficient vector. */
  int
  offset (int region) const
  {
    return offsets_[region];
  }

  /** \brief Length of the stacked coefficient vector (the number P of shape parameters). */
  int
  total () const
  {
    return offsets_.back ();
  }

  const std::vector<int>&
  counts () const
  {
    return counts_;
  }

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
