// A caller's say over the improvement pass: shown every plan the pass is about to apply, after
// the pass's own tests passed it (the operator's, the quality, the uncuttable tissue), it lets the
// plan through (Refusal::kNone) or vetoes it with a reason (Refusal::kVetoed, or one more
// telling). A vetoed plan is not applied, and the pass goes on as if the operator had refused it.
//
// What the hook sees is the plan (operation.hpp): the tets it removes, the tets it adds as vertex
// quadruples, and the vertex it places with its new position; Plan::corners() gives an added
// tet's corners where they will be. An insertion is shown after its split (and the smoothing of
// its new point, shown on its own first), as the new point's star then is: vetoed, it is rolled
// back to the savepoint before the split.
//
// Non-owning, like the function_ref the standard is getting: it holds the address of the
// caller's callable, which must outlive the run, and calls it through one function pointer per
// plan (never per tet), allocating nothing. Empty, it lets everything through.
#pragma once

#include <type_traits>

#include "improve/operation.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

class PlanVeto {
 public:
  PlanVeto() = default;
  template <class F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, PlanVeto> &&
             std::is_invocable_r_v<Refusal, const F&, const TetMesh&, const Plan&>)
  PlanVeto(const F& hook)  // NOLINT(google-explicit-constructor): a callable is a veto
      : hook_(&hook), call_([](const void* h, const TetMesh& mesh, const Plan& plan) -> Refusal {
          return (*static_cast<const F*>(h))(mesh, plan);
        }) {}
  // A temporary would be gone before the run calls it.
  template <class F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, PlanVeto> && !std::is_lvalue_reference_v<F>)
  PlanVeto(F&&) = delete;

  [[nodiscard]] explicit operator bool() const { return call_ != nullptr; }
  // kNone: the plan may go ahead; otherwise why not.
  [[nodiscard]] Refusal operator()(const TetMesh& mesh, const Plan& plan) const {
    return call_ ? call_(hook_, mesh, plan) : Refusal::kNone;
  }

 private:
  const void* hook_ = nullptr;
  Refusal (*call_)(const void*, const TetMesh&, const Plan&) = nullptr;
};

}  // namespace tetcut::detail
