// The results of a batch as wrc.Batch reads them (python/wrc/batch.py): each element's described result stays a
// recorded tree (wrc/core/field_record.hpp) after the run; a field is stacked over the batch when first read (one
// numpy array filled from the trees in one pass, no Python object per element), and each element's wrc.Result is
// made from its tree only when Batch.items is first read. Making ~200 Results per wheel solve serially after the
// parallel solves was most of a batch's cost beyond the solves.
#pragma once

#include "python/bindings.hpp"
#include "wrc/core/field_record.hpp"

#include <memory>
#include <vector>

namespace wrc::python {

// The elements' described results: records[i] is element i's (an empty table when it has none).
struct BatchTrees {
  std::vector<FieldRecord> records;
};

// The wrc._wrc._BatchNodes of the elements' roots: present[i] says element i has a result in the arrays (the others
// are missing: NaN in the fields, None in items).
py::object batch_nodes(std::shared_ptr<const BatchTrees> trees, const std::vector<bool>& present);

void register_batch_fields(py::module_& m);

}  // namespace wrc::python
