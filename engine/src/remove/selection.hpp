// The tets a caller (a cut) selected for removal, as the removal stage reads them: a request
// counts the selected tets a neighbour set swallowed (paper 3.6's cardinality per selected tet),
// and a refinement takes a selected parent's other children along (removal_context.hpp). The
// cut marks them (cut_pipeline.cpp); the Remover and its strategies only read.
#pragma once

#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/ids.hpp"

namespace tetcut {

using Selection = StampedSet<TetId>;

}  // namespace tetcut
