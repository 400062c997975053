// The tissue rule, as the improvement pass must keep it (the cut's audit and the checker's I10
// hold the whole cut to it: tissue_audit.hpp). Asked of every plan the pass would apply
// (improve/plan_veto.hpp), it refuses one that would make
//   - a tet meeting the tool with an edge longer than D_ref: the refinement made the tool's
//     neighbourhood fine, and a flip or a collapse there must not make it coarse again; or
//   - a cuttable tet with its centroid in the tool and its edges within D_ref: tissue the cut
//     takes, which no request of the removal stage, over by then, would ever take.
// A plan among uncuttable tets makes only uncuttable ones (the pass flips only among tets of one
// kind), which the rule does not take.
#pragma once

#include "core/uncuttable_tets.hpp"
#include "cut/tissue_selection.hpp"
#include "improve/operation.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

class TissueRuleVeto {
 public:
  TissueRuleVeto(TetMesh& mesh, const TissueSelection& selection, const UncuttableTets& uncuttable, double d_ref)
      : mesh_(mesh), selection_(selection), uncuttable_(uncuttable), d_ref_(d_ref) {}
  Refusal operator()(const TetMesh& mesh, const Plan& plan) const;

 private:
  TetMesh& mesh_;  // the same mesh, for the uncuttable set's journal lookups
  const TissueSelection& selection_;
  const UncuttableTets& uncuttable_;
  double d_ref_;
};

}  // namespace tetcut::detail
