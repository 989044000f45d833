// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/model/component_selection.h>

namespace morphreg
{
ComponentSelection::ComponentSelection (std::vector<int> counts) : counts_ (std::move (counts)), offsets_ (1, 0)
{
  for (size_t j = 0; j < counts_.size (); ++j) {
    if (counts_[j] < 0)
      throw InvalidInputError ("ComponentSelection: region " + std::to_string (j) + " has a negative count " +
                               std::to_string (counts_[j]));
    offsets_.push_back (offsets_.back () + counts_[j]);
  }
}

} // namespace morphreg
