#include "tetcut/removal.hpp"

#include <algorithm>
#include <cassert>

#include "tetcut/local_tables.hpp"

namespace tetcut {
namespace {

// Two candidate sets of one round are kept for the next one: enough for the paper's "path
// extended by each of the two components", small enough to bound the work.
constexpr std::size_t kFrontierWidth = 4;

// Splits in one refinement attempt: the first around the singularity, then one per vertex the
// search still stumbles on (a tet has four vertices).
constexpr int kMaxRefinementLevels = 5;

int local_edge_of(const TetMesh& mesh, TetId t, VertId a, VertId b) {
  const int la = mesh.local_index(t, a), lb = mesh.local_index(t, b);
  assert(la >= 0 && lb >= 0 && la != lb);
  return kEdgeIndex[la][lb];
}

bool contains_all(const TetMesh& mesh, TetId t, std::span<const VertId> verts) {
  for (VertId v : verts)
    if (mesh.local_index(t, v) < 0) return false;
  return true;
}

bool contains_any(const TetMesh& mesh, TetId t, std::span<const VertId> verts) {
  for (VertId v : verts)
    if (mesh.local_index(t, v) >= 0) return true;
  return false;
}

}  // namespace

const char* to_string(RemovalStrategy strategy) {
  switch (strategy) {
    case RemovalStrategy::kBasic: return "basic";
    case RemovalStrategy::kNeighbours: return "neighbours";
    case RemovalStrategy::kCombined: return "combined";
  }
  return "?";
}

std::optional<RemovalStrategy> parse_removal_strategy(std::string_view text) {
  if (text == "basic") return RemovalStrategy::kBasic;
  if (text == "neighbours" || text == "neighbors") return RemovalStrategy::kNeighbours;
  if (text == "combined") return RemovalStrategy::kCombined;
  return std::nullopt;
}

const char* to_string(RemovalOutcome outcome) {
  switch (outcome) {
    case RemovalOutcome::kDirect: return "direct";
    case RemovalOutcome::kNeighbours: return "neighbours";
    case RemovalOutcome::kRefinement: return "refinement";
    case RemovalOutcome::kFlood: return "flood";
    case RemovalOutcome::kUnresolved: return "unresolved";
  }
  return "?";
}

double RemovalReport::mean_cardinality() const {
  const std::uint64_t n = direct + resolved_by_neighbours;
  if (n == 0) return 0.0;
  return static_cast<double>(direct + neighbour_set_tets) / static_cast<double>(n);
}

RemovalReport& RemovalReport::operator+=(const RemovalReport& o) {
  requested += o.requested;
  repeated_requests += o.repeated_requests;
  removed += o.removed;
  unresolved += o.unresolved;
  direct += o.direct;
  vertex_singularities += o.vertex_singularities;
  edge_singularities += o.edge_singularities;
  resolved_by_neighbours += o.resolved_by_neighbours;
  vertex_resolved_by_neighbours += o.vertex_resolved_by_neighbours;
  edge_resolved_by_neighbours += o.edge_resolved_by_neighbours;
  resolved_by_refinement += o.resolved_by_refinement;
  resolved_by_optimized_refinement += o.resolved_by_optimized_refinement;
  resolved_by_flood += o.resolved_by_flood;
  neighbour_set_tets += o.neighbour_set_tets;
  vertex_neighbour_set_tets += o.vertex_neighbour_set_tets;
  edge_neighbour_set_tets += o.edge_neighbour_set_tets;
  tets_removed += o.tets_removed;
  tets_created += o.tets_created;
  edges_split += o.edges_split;
  refinements_undone += o.refinements_undone;
  return *this;
}

Remover::Remover(RemovalOptions options) : options_(options) {}

void Remover::reserve(std::uint32_t tets, std::uint32_t vertices) {
  if (tet_stamp_.size() < tets) {
    tet_stamp_.resize(tets, 0);
    met_unresolved_.resize(tets, 0);
    created_stamp_.resize(tets, 0);
    removed_stamp_.resize(tets, 0);
    attempt_stamp_.resize(tets, 0);
    aux_stamp_.resize(tets, 0);
  }
  ws_.reserve(tets, vertices);
  splitter_.reserve(tets);
}

void Remover::grow_tet_arrays(const TetMesh& mesh) {
  if (tet_stamp_.size() >= mesh.tet_capacity()) return;
  const std::size_t n = mesh.tet_capacity() + mesh.tet_capacity() / 4 + 16;
  tet_stamp_.resize(n, 0);
  met_unresolved_.resize(n, 0);
  created_stamp_.resize(n, 0);
  removed_stamp_.resize(n, 0);
  attempt_stamp_.resize(n, 0);
  aux_stamp_.resize(n, 0);
}

void Remover::note_removed(std::span<const TetId> ids) {
  for (TetId r : ids) {
    met_unresolved_[r.value] = 0;
    if (created_stamp_[r.value] == op_) {
      // Made and unmade within this request: not part of the net change (if the id was live
      // before the request as well, it is already in net_removed_).
      created_stamp_[r.value] = 0;
      net_created_.erase(std::find(net_created_.begin(), net_created_.end(), r));
    } else if (removed_stamp_[r.value] != op_) {
      removed_stamp_[r.value] = op_;
      net_removed_.push_back(r);
    }
  }
}

void Remover::note_created(std::span<const TetId> ids) {
  for (TetId c : ids) {
    created_stamp_[c.value] = op_;
    net_created_.push_back(c);
  }
}

void Remover::apply_removal(TetMesh& mesh, std::span<const TetId> set) {
  ws_.mark(mesh, set);
  for (TetId u : set)
    for (int f = 0; f < 4; ++f) {
      const FaceRef n = mesh.neighbour(u, f);
      if (n.valid() && !ws_.marked(n.tet)) exposed_.push_back(n.tet);
    }
  if (log_) log_->removed.insert(log_->removed.end(), set.begin(), set.end());
  note_removed(set);
  mesh.remove_tets(set);
}

// ---- the neighbour search (paper 3.5) ---------------------------------------------------------

void Remover::add_candidate(std::uint32_t begin, std::uint32_t size, std::span<const TetId> extra) {
  if (extra.empty() || size + extra.size() > options_.max_set_size) return;
  Candidate c;
  c.begin = static_cast<std::uint32_t>(pool_.size());
  c.size = size + static_cast<std::uint32_t>(extra.size());
  for (std::uint32_t i = begin; i < begin + size; ++i) {
    const TetId x = pool_[i];  // a copy: push_back may reallocate pool_
    pool_.push_back(x);
  }
  pool_.insert(pool_.end(), extra.begin(), extra.end());
  candidates_.push_back(c);
}

void Remover::expand(const TetMesh& mesh, const Candidate& from) {
  ws_.mark(mesh, std::span<const TetId>(pool_.data() + from.begin, from.size));
  const SetRemovalCheck& off = from.offence;
  tmp_tets_.clear();
  tmp_sizes_.clear();
  auto part = [&](std::size_t offset, std::size_t n) {
    return std::span<const TetId>(tmp_tets_.data() + offset, n);
  };
  if (off.kind == SingularityKind::kEdge) {
    // Around the edge the remaining tets form several runs: remove all but one of them. With
    // the requested tet alone these are the paper's "left set" and "right set"; all of them is
    // its "whole set of adjacent tetrahedra".
    ws_.remaining_runs(mesh, off.tet, off.local_edge, tmp_tets_, tmp_sizes_);
    std::size_t offset = 0;
    for (std::uint32_t n : tmp_sizes_) {
      add_candidate(from.begin, from.size, part(offset, n));
      offset += n;
    }
    if (tmp_sizes_.size() >= 2) add_candidate(from.begin, from.size, part(0, tmp_tets_.size()));
  } else if (off.kind == SingularityKind::kVertex) {
    ws_.remaining_components(mesh, off.vertex, off.tet, tmp_tets_, tmp_sizes_);
    // The shell falls apart: take one component along (paper 3.5's extension heuristic).
    if (tmp_sizes_.size() >= 2) {
      std::size_t offset = 0;
      for (std::uint32_t n : tmp_sizes_) {
        add_candidate(from.begin, from.size, part(offset, n));
        offset += n;
      }
    }
    // A hole in the shell: open it onto the surface by the shortest path (paper 3.5, fig. 4).
    tmp_path_.clear();
    if (ws_.path_to_border(mesh, off.vertex, off.tet, options_.max_path_depth, tmp_path_))
      add_candidate(from.begin, from.size, tmp_path_);
    // Last resort: the vertex goes entirely.
    add_candidate(from.begin, from.size, part(0, tmp_tets_.size()));
  }
}

bool Remover::search(const TetMesh& mesh, std::span<const TetId> seed, const SetRemovalCheck& offence,
                     std::vector<TetId>& out) {
  pool_.assign(seed.begin(), seed.end());
  frontier_.clear();
  Candidate start;
  start.begin = 0;
  start.size = static_cast<std::uint32_t>(seed.size());
  start.offence = offence;
  frontier_.push_back(start);
  int evaluations = 0;
  for (int round = 0; round < options_.max_rounds; ++round) {
    candidates_.clear();
    for (const Candidate& f : frontier_) expand(mesh, f);
    if (candidates_.empty()) return false;
    // Smallest first (the paper keeps the smallest removable set); ties in generation order.
    std::sort(candidates_.begin(), candidates_.end(), [](const Candidate& x, const Candidate& y) {
      return x.size != y.size ? x.size < y.size : x.begin < y.begin;
    });
    next_frontier_.clear();
    for (Candidate& c : candidates_) {
      if (evaluations >= options_.max_evaluations) return false;
      const std::span<const TetId> set(pool_.data() + c.begin, c.size);
      const SetRemovalCheck check = ws_.check(mesh, set);
      ++evaluations;
      if (check.ok) {
        out.assign(set.begin(), set.end());
        return true;
      }
      if (next_frontier_.size() < kFrontierWidth) {
        c.offence = check;
        next_frontier_.push_back(c);
      }
    }
    frontier_.swap(next_frontier_);
  }
  return false;
}

// ---- refinement (paper 3.4 and 3.7) -------------------------------------------------------------

bool Remover::refine_vertex(TetMesh& mesh, TetId& t, VertId v, bool optimized, RemovalResult& result) {
  seed_parents_.clear();
  if (optimized) {
    // 3.7: only the edges at v of the tets on the shortest path from T to the shell's border.
    const TetId one[1] = {t};
    ws_.mark(mesh, one);
    tmp_path_.clear();
    if (!ws_.path_to_border(mesh, v, t, options_.max_path_depth, tmp_path_)) return false;
    seed_parents_.push_back(t);
    seed_parents_.insert(seed_parents_.end(), tmp_path_.begin(), tmp_path_.end());
  } else {
    // 3.4: every edge at v.
    mesh.vertex_shell(v, shell_);
    seed_parents_.assign(shell_.begin(), shell_.end());
  }
  edges_.clear();
  edge_refs_.clear();
  edge_set_.clear();
  for (TetId u : seed_parents_)
    for (int i = 0; i < 4; ++i) {
      const VertId w = mesh.vertex(u, i);
      if (w == v || !edge_set_.insert(v, w)) continue;
      edges_.push_back({v, w});
      edge_refs_.push_back({u, static_cast<std::uint8_t>(local_edge_of(mesh, u, v, w))});
    }
  const VertId keep[1] = {v};
  if (!split_and_remove(mesh, t, keep, result)) return false;
  result.optimized_refinement = optimized;
  return true;
}

bool Remover::refine_edge(TetMesh& mesh, TetId& t, Edge e, int side, RemovalResult& result) {
  const TetId one[1] = {t};
  ws_.mark(mesh, one);
  tmp_tets_.clear();
  tmp_sizes_.clear();
  ws_.remaining_runs(mesh, t, local_edge_of(mesh, t, e.a, e.b), tmp_tets_, tmp_sizes_);
  seed_parents_.clear();
  seed_parents_.push_back(t);
  if (side < 0) {
    seed_parents_.insert(seed_parents_.end(), tmp_tets_.begin(), tmp_tets_.end());
  } else {
    // 3.7: the left or the right set, the smaller one first.
    if (tmp_sizes_.size() != 2) return false;
    const bool first_smaller = tmp_sizes_[0] <= tmp_sizes_[1];
    const bool take_first = (side == 0) == first_smaller;
    const auto begin = tmp_tets_.begin() + (take_first ? 0 : tmp_sizes_[0]);
    seed_parents_.insert(seed_parents_.end(), begin, begin + (take_first ? tmp_sizes_[0] : tmp_sizes_[1]));
  }
  // The edges of those tets that touch e (e itself stays).
  edges_.clear();
  edge_refs_.clear();
  edge_set_.clear();
  for (TetId u : seed_parents_)
    for (int i = 0; i < 4; ++i) {
      const VertId x = mesh.vertex(u, i);
      if (x == e.a || x == e.b) continue;
      for (VertId end : {e.a, e.b}) {
        if (!edge_set_.insert(end, x)) continue;
        edges_.push_back({end, x});
        edge_refs_.push_back({u, static_cast<std::uint8_t>(local_edge_of(mesh, u, end, x))});
      }
    }
  const VertId keep[2] = {e.a, e.b};
  if (!split_and_remove(mesh, t, keep, result)) return false;
  result.optimized_refinement = side >= 0;
  return true;
}

bool Remover::flood(TetMesh& mesh, TetId t, RemovalResult& result) {
  if (!mesh.is_live(t)) return false;
  const std::uint32_t in_set = fresh_stamp();
  flood_.assign(1, t);
  aux_stamp_[t.value] = in_set;
  for (;;) {
    const SetRemovalCheck c = ws_.check(mesh, flood_);
    if (c.ok) break;
    if (c.kind == SingularityKind::kVertex) {
      mesh.vertex_shell(c.vertex, shell_);
    } else {
      mesh.edge_shell(c.tet, c.local_edge, shell_);
    }
    std::size_t added = 0;
    for (TetId u : shell_)
      if (aux_stamp_[u.value] != in_set) {
        aux_stamp_[u.value] = in_set;
        flood_.push_back(u);
        ++added;
      }
    // An offence always has tets left around it, so every round grows the set; the guard only
    // protects against a broken invariant.
    if (added == 0) return false;
  }
  apply_removal(mesh, flood_);
  result.tets_removed = static_cast<std::uint32_t>(flood_.size());
  return true;
}

std::uint32_t Remover::fresh_stamp() {
  if (++stamp_ == 0) {
    std::fill(tet_stamp_.begin(), tet_stamp_.end(), 0u);
    std::fill(aux_stamp_.begin(), aux_stamp_.end(), 0u);
    stamp_ = 1;
  }
  return stamp_;
}

bool Remover::split_edges(TetMesh& mesh, RemovalResult& result) {
  grow_tet_arrays(mesh);
  // The tets the split will replace; those that existed before the attempt are saved.
  const std::uint32_t in_region = fresh_stamp();
  region_.clear();
  for (const EdgeRef& ref : edge_refs_) {
    mesh.edge_shell(ref.tet, ref.edge, ring_);
    for (TetId u : ring_) {
      if (aux_stamp_[u.value] == in_region) continue;
      aux_stamp_[u.value] = in_region;
      region_.push_back(u);
    }
  }
  const std::size_t saved_before = original_ids_.size();
  for (TetId u : region_)
    if (attempt_stamp_[u.value] != attempt_) {
      original_ids_.push_back(u);
      original_verts_.push_back(mesh.tet(u));
    }

  split_log_.clear();
  const SplitResult split = splitter_.split(mesh, edges_, SplitMethod::kTemplates, nullptr, &split_log_);
  if (!split.ok()) {
    original_ids_.resize(saved_before);
    original_verts_.resize(saved_before);
    return false;
  }
  assert(split_log_.removed.size() == region_.size());
  grow_tet_arrays(mesh);
  note_removed(split_log_.removed);
  children_.clear();
  for (const CreatedTet& c : split_log_.created) {
    children_.push_back(c.tet);
    attempt_stamp_[c.tet.value] = attempt_;
    attempt_created_.push_back(c.tet);
  }
  note_created(children_);
  if (log_) {
    log_->removed.insert(log_->removed.end(), split_log_.removed.begin(), split_log_.removed.end());
    log_->created.insert(log_->created.end(), split_log_.created.begin(), split_log_.created.end());
    log_->vertices.insert(log_->vertices.end(), split_log_.vertices.begin(), split_log_.vertices.end());
  }
  for (const CreatedVertex& cv : split_log_.vertices) {
    if (vert_attempt_stamp_.size() <= cv.vertex.value)
      vert_attempt_stamp_.resize(cv.vertex.value + cv.vertex.value / 4 + 16, 0);
    vert_attempt_stamp_[cv.vertex.value] = attempt_;
  }
  result.tets_created += split.tets_created;
  result.edges_split += split.edges_split;
  return true;
}

TetId Remover::undo_attempt(TetMesh& mesh, std::size_t t_index) {
  // Every live tet the attempt made (an id seen twice was reused by a later split: once).
  const std::uint32_t seen = fresh_stamp();
  children_.clear();
  for (TetId c : attempt_created_) {
    if (!mesh.is_live(c) || attempt_stamp_[c.value] != attempt_ || aux_stamp_[c.value] == seen) continue;
    aux_stamp_[c.value] = seen;
    children_.push_back(c);
  }
  // They fill exactly the region of the tets they replaced, with the same outer faces: the
  // original tets glue back, and the midpoints lose their last tet and go.
  restored_.clear();
  if (log_) log_->removed.insert(log_->removed.end(), children_.begin(), children_.end());
  note_removed(children_);
  mesh.replace_tets(children_, original_verts_, &restored_);
  grow_tet_arrays(mesh);
  note_created(restored_);
  if (log_)
    for (TetId r : restored_) log_->created.push_back({r, kNoTet});
  ++report_.refinements_undone;
  return restored_[t_index];
}

bool Remover::refine_tet_corners(TetMesh& mesh, TetId& t, RemovalResult& result) {
  VertId corners[4];
  std::size_t n = 0;
  for (VertId p : mesh.tet(t))
    if (mesh.is_boundary_vertex(p)) corners[n++] = p;
  if (n == 0) return false;
  seed_parents_.clear();
  edges_.clear();
  edge_refs_.clear();
  edge_set_.clear();
  const std::uint32_t seen = fresh_stamp();
  for (std::size_t k = 0; k < n; ++k) {
    mesh.vertex_shell(corners[k], shell_);
    for (TetId u : shell_) {
      if (aux_stamp_[u.value] != seen) {
        aux_stamp_[u.value] = seen;
        seed_parents_.push_back(u);
      }
      for (int i = 0; i < 4; ++i) {
        const VertId w = mesh.vertex(u, i);
        if (w == corners[k] || !edge_set_.insert(corners[k], w)) continue;
        edges_.push_back({corners[k], w});
        edge_refs_.push_back({u, static_cast<std::uint8_t>(local_edge_of(mesh, u, corners[k], w))});
      }
    }
  }
  return split_and_remove(mesh, t, std::span<const VertId>(corners, n), result, true);
}

bool Remover::split_and_remove(TetMesh& mesh, TetId& t, std::span<const VertId> keep, RemovalResult& result,
                               bool keep_any) {
  grow_tet_arrays(mesh);
  if (++attempt_ == 0) {
    std::fill(attempt_stamp_.begin(), attempt_stamp_.end(), 0u);
    std::fill(vert_attempt_stamp_.begin(), vert_attempt_stamp_.end(), 0u);
    attempt_ = 1;
  }
  attempt_created_.clear();
  original_ids_.clear();
  original_verts_.clear();
  const RemovalResult before = result;

  const std::uint32_t is_seed = fresh_stamp();
  for (TetId u : seed_parents_) tet_stamp_[u.value] = is_seed;
  if (!split_edges(mesh, result)) return false;  // refused before touching the mesh
  const auto t_at = std::find(original_ids_.begin(), original_ids_.end(), t);
  assert(t_at != original_ids_.end());
  const std::size_t t_index = static_cast<std::size_t>(t_at - original_ids_.begin());

  // The small tets at the singularity on the chosen tets, with all of T's children.
  x_.clear();
  bool t_split = false;
  for (const CreatedTet& c : split_log_.created) {
    if (c.parent == t) {
      t_split = true;
      x_.push_back(c.tet);
    } else if (tet_stamp_[c.parent.value] == is_seed &&
               (keep_any ? contains_any(mesh, c.tet, keep) : contains_all(mesh, c.tet, keep))) {
      x_.push_back(c.tet);
    }
  }
  if (!t_split) x_.push_back(t);

  for (int level = 0;; ++level) {
    const SetRemovalCheck check = ws_.check(mesh, x_);
    bool ok = check.ok;
    if (ok) {
      found_.assign(x_.begin(), x_.end());
    } else {
      restored_.assign(x_.begin(), x_.end());  // search() overwrites found_ only on success
      ok = search(mesh, restored_, check, found_);
    }
    if (ok) {
      result.tets_removed = static_cast<std::uint32_t>(found_.size());
      apply_removal(mesh, found_);
      return true;
    }
    if (level + 1 >= kMaxRefinementLevels) break;

    // Escalate at the offending vertex: an original vertex rather than a midpoint of this
    // attempt (a midpoint's trouble comes from the vertex at the other end of its edge).
    VertId a = check.vertex;
    if (check.kind == SingularityKind::kEdge) {
      const VertId ea = check.edge.a;
      const bool ea_is_new = ea.value < vert_attempt_stamp_.size() && vert_attempt_stamp_[ea.value] == attempt_;
      a = ea_is_new ? check.edge.b : ea;
    }
    const std::uint32_t in_x = fresh_stamp();
    for (TetId u : x_) tet_stamp_[u.value] = in_x;
    mesh.vertex_shell(a, shell_);
    edges_.clear();
    edge_refs_.clear();
    edge_set_.clear();
    for (TetId u : shell_)
      for (int i = 0; i < 4; ++i) {
        const VertId w = mesh.vertex(u, i);
        if (w == a || !edge_set_.insert(a, w)) continue;
        edges_.push_back({a, w});
        edge_refs_.push_back({u, static_cast<std::uint8_t>(local_edge_of(mesh, u, a, w))});
      }
    if (!split_edges(mesh, result)) break;
    // The set follows the split (children of its tets), plus every small tet now at a.
    const std::uint32_t gone = fresh_stamp();
    for (TetId r : split_log_.removed) aux_stamp_[r.value] = gone;
    x_next_.clear();
    for (TetId u : x_)
      if (aux_stamp_[u.value] != gone) x_next_.push_back(u);
    for (const CreatedTet& c : split_log_.created)
      if (tet_stamp_[c.parent.value] == in_x || mesh.local_index(c.tet, a) >= 0) x_next_.push_back(c.tet);
    x_.swap(x_next_);
  }

  t = undo_attempt(mesh, t_index);
  result = before;
  return false;
}

// ---- one request ------------------------------------------------------------------------------

RemovalResult Remover::remove(TetMesh& mesh, TetId t, ChangeLog* log) {
  assert(mesh.is_live(t));
  log_ = log;
  grow_tet_arrays(mesh);
  if (++op_ == 0) {
    std::fill(created_stamp_.begin(), created_stamp_.end(), 0u);
    std::fill(removed_stamp_.begin(), removed_stamp_.end(), 0u);
    op_ = 1;
  }
  net_removed_.clear();
  net_created_.clear();
  exposed_.clear();

  RemovalResult result;
  result.first = removability(mesh, t);
  const bool repeat = met_unresolved_[t.value] != 0;

  SetRemovalCheck offence;
  if (result.first.removable) {
    if (options_.verify_direct) {
      const TetId one[1] = {t};
      offence = ws_.check(mesh, one);
      assert(offence.ok && "removability() and set_removable() disagree");
    }
  } else {
    offence.ok = false;
    offence.kind = result.first.kind;
    offence.tet = t;
    offence.vertex = result.first.vertex;
    offence.edge = result.first.edge;
    if (offence.kind == SingularityKind::kEdge)
      offence.local_edge = static_cast<std::uint8_t>(local_edge_of(mesh, t, offence.edge.a, offence.edge.b));
  }
  const SingularityKind kind = offence.kind;

  bool done = false;
  if (offence.ok) {
    const TetId one[1] = {t};
    apply_removal(mesh, one);
    result.outcome = RemovalOutcome::kDirect;
    result.tets_removed = 1;
    done = true;
  }
  if (!done && options_.strategy != RemovalStrategy::kBasic) {
    const TetId one[1] = {t};
    if (search(mesh, one, offence, found_)) {
      result.outcome = RemovalOutcome::kNeighbours;
      result.tets_removed = static_cast<std::uint32_t>(found_.size());
      apply_removal(mesh, found_);
      done = true;
    }
  }
  if (!done && options_.strategy == RemovalStrategy::kCombined) {
    if (kind == SingularityKind::kVertex) {
      done = refine_vertex(mesh, t, offence.vertex, true, result);
    } else {
      done = refine_edge(mesh, t, offence.edge, 0, result) || refine_edge(mesh, t, offence.edge, 1, result);
    }
    if (done) result.outcome = RemovalOutcome::kRefinement;
  }
  if (!done && options_.strategy != RemovalStrategy::kNeighbours) {
    done = kind == SingularityKind::kVertex ? refine_vertex(mesh, t, offence.vertex, false, result)
                                            : refine_edge(mesh, t, offence.edge, -1, result);
    if (!done) done = refine_tet_corners(mesh, t, result);
    if (done) result.outcome = RemovalOutcome::kRefinement;
  }
  // Every request must go under basic and combined: the paper's sets and our bounded searches
  // cover almost every case, and the flood covers the rest (found by the cut_sequence fuzzer:
  // one cut on the cylinder left a tet none of the above could take).
  if (!done && options_.strategy != RemovalStrategy::kNeighbours && flood(mesh, t, result)) {
    done = true;
    result.outcome = RemovalOutcome::kFlood;
  }

  // Statistics, a tet met again after being left unresolved counting once.
  RemovalReport& r = report_;
  if (repeat) {
    ++r.repeated_requests;
  } else {
    ++r.requested;
    if (kind == SingularityKind::kVertex) ++r.vertex_singularities;
    if (kind == SingularityKind::kEdge) ++r.edge_singularities;
  }
  if (done) {
    ++r.removed;
    if (repeat) --r.unresolved;
    r.tets_removed += result.tets_removed;
    r.tets_created += result.tets_created;
    r.edges_split += result.edges_split;
  }
  switch (result.outcome) {
    case RemovalOutcome::kDirect:
      if (!repeat) ++r.direct;
      break;
    case RemovalOutcome::kNeighbours:
      ++r.resolved_by_neighbours;
      r.neighbour_set_tets += result.tets_removed;
      if (kind == SingularityKind::kVertex) {
        ++r.vertex_resolved_by_neighbours;
        r.vertex_neighbour_set_tets += result.tets_removed;
      } else {
        ++r.edge_resolved_by_neighbours;
        r.edge_neighbour_set_tets += result.tets_removed;
      }
      break;
    case RemovalOutcome::kRefinement:
      ++r.resolved_by_refinement;
      if (result.optimized_refinement) ++r.resolved_by_optimized_refinement;
      break;
    case RemovalOutcome::kFlood:
      ++r.resolved_by_flood;
      break;
    case RemovalOutcome::kUnresolved:
      if (!repeat) ++r.unresolved;
      // The id may have changed if a refinement was undone: flag the tet that stands there now.
      met_unresolved_[t.value] = 1;
      break;
  }

  for (TetId c : net_created_)
    if (mesh.is_live(c) && mesh.boundary_face_count(c) > 0) exposed_.push_back(c);
  log_ = nullptr;
  return result;
}

// ---- picking tets as a cautery meets them -----------------------------------------------------

BoundaryTetPicker::BoundaryTetPicker(const TetMesh& mesh, std::uint64_t seed) : rng_(seed) {
  in_pool_.assign(mesh.tet_capacity(), 0);
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    const TetId t{i};
    if (mesh.is_live(t) && mesh.boundary_face_count(t) > 0) {
      pool_.push_back(t);
      in_pool_[i] = 1;
    }
  }
}

void BoundaryTetPicker::add(std::span<const TetId> tets) {
  for (TetId t : tets) {
    if (t.value >= in_pool_.size()) in_pool_.resize(t.value + t.value / 4 + 16, 0);
    if (in_pool_[t.value]) continue;
    in_pool_[t.value] = 1;
    pool_.push_back(t);
  }
}

TetId BoundaryTetPicker::pick(const TetMesh& mesh) {
  while (!pool_.empty()) {
    const std::uint32_t i = rng_.below(static_cast<std::uint32_t>(pool_.size()));
    const TetId t = pool_[i];
    if (mesh.is_live(t) && mesh.boundary_face_count(t) > 0) return t;
    // Gone (or no longer on the surface): drop it.
    in_pool_[t.value] = 0;
    pool_[i] = pool_.back();
    pool_.pop_back();
  }
  return kNoTet;
}

}  // namespace tetcut
