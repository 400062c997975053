// Called once per cut; does nothing in the engine (see planted_slowdown.cpp).
#pragma once

namespace tetcut::detail {

void planted_slowdown();

}  // namespace tetcut::detail
