/* tetcut/harness/engine.h: the C interface any cutting engine implements so that tetcut's harness
 * (the independent checker after every operation, the sequence fuzzers, minimization, the peers
 * benchmark) can drive it. Plain C99, so that an adapter for SOFA, iMSTK, VTK or a private engine
 * is written in C or C++ and built without tetcut: it includes this one header and nothing else.
 *
 * An adapter is a shared library that exports one function, tetcut_engine_adapter(), returning a
 * table of function pointers (tetcut_engine_api). The harness loads it at run time
 * (`tetcut check-engine --engine libmy_adapter.so`) and runs it in a child process, so that a
 * crash in the engine is reported with its signal, the adapter and the operation, and the harness
 * survives it. docs/engines.md shows how an adapter is written; examples/engine_adapter/ is the
 * template.
 *
 * The mesh crosses the interface as two flat arrays, as a file holds it:
 *   points  3 doubles per vertex (x, y, z);
 *   tets    4 vertex indices per tet, 0-based, positively oriented (the orientation of points
 *           1, 2, 3 seen from point 0 is counter-clockwise: det(p1 - p0, p2 - p0, p3 - p0) > 0);
 *           a tet whose first index is TETCUT_ENGINE_DEAD_TET is a removed tet kept in place
 *           (a tombstone), so that an engine that never renumbers keeps its tet ids stable.
 * A tet id is its index in the tets array as the adapter last returned it from mesh(), or, before
 * the first mesh() call, in the array create() was given.
 *
 * Ownership: every array passed to the adapter is the harness's and is valid only during the
 * call (copy what you keep). Every array the adapter returns (mesh(), changes(), name, version,
 * last_error()) is the adapter's and must stay valid and unchanged until the next call on the
 * same engine (or, for name and version, for as long as the library is loaded).
 *
 * Errors: an operation returns TETCUT_ENGINE_OK, TETCUT_ENGINE_REFUSED (the engine declines it
 * and the mesh is exactly as before: a CGAL complex refusing a removal that would make it
 * singular) or TETCUT_ENGINE_ERROR (the engine failed; last_error() says why in one line; the
 * harness reports it and stops driving that engine). create() returns NULL on failure and writes
 * one line into its error buffer. Anything else the harness finds (a null array, an index out of
 * range, a version it does not know) is reported naming the adapter and the operation.
 *
 * Threads: the harness calls one engine from one thread; engines are never shared.
 *
 * Versions: TETCUT_ENGINE_ABI_VERSION grows when a member is added at the end of a struct; the
 * harness reads only the members the adapter's abi_version has. Version 1 is this header.
 */
#ifndef TETCUT_HARNESS_ENGINE_H
#define TETCUT_HARNESS_ENGINE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define TETCUT_ENGINE_ABI_VERSION 1u

/* The name of the one symbol an adapter library exports (for dlsym). */
#define TETCUT_ENGINE_ENTRY_POINT "tetcut_engine_adapter"

/* The first index of a removed tet kept in place. */
#define TETCUT_ENGINE_DEAD_TET 0xFFFFFFFFu

/* What an operation returns. */
enum tetcut_engine_status {
  TETCUT_ENGINE_OK = 0,
  TETCUT_ENGINE_REFUSED = 1, /* declined; the mesh is exactly as before */
  TETCUT_ENGINE_ERROR = 2    /* failed; last_error() says why */
};

/* What an engine offers beyond the required operations (tetcut_engine_api::capabilities). */
enum tetcut_engine_capability {
  /* cut_capsule is set: a tool swept along a segment. */
  TETCUT_ENGINE_CAPSULE = 1u << 0,
  /* changes is set and tet ids are stable (removed tets stay as tombstones, new tets are added or
     reuse dead ids): the harness checks only what each operation touched (O(operation)) instead
     of the whole mesh. */
  TETCUT_ENGINE_CHANGE_LOG = 1u << 1,
  /* The engine promises tetcut's no-degradation rule (invariant I7: a cut's new tets are no
     worse than min(floor, the tets they replace)); without it quality is reported, not judged. */
  TETCUT_ENGINE_QUALITY_FLOOR = 1u << 2,
  /* The engine promises tetcut's tissue rule (invariant I10: after a cut no tet with its centroid
     in the tool and its edges within d_ref remains, but those it lists as left). Needs
     TETCUT_ENGINE_CHANGE_LOG (d_ref and the left tets come with the changes). */
  TETCUT_ENGINE_TISSUE_RULE = 1u << 3
};

/* The adapter's engine: opaque to the harness. */
typedef struct tetcut_engine tetcut_engine;

/* A mesh as flat arrays (see the top of this file). */
typedef struct tetcut_engine_mesh {
  const double* points;   /* 3 * point_count */
  uint32_t point_count;
  const uint32_t* tets;   /* 4 * tet_count, tombstones allowed */
  uint32_t tet_count;
} tetcut_engine_mesh;

/* A vertex that was there before the operation and that it moved: its new position is the sum
   over i < count of weight[i] * (the position of from[i] before the operation). */
typedef struct tetcut_engine_moved_vertex {
  uint32_t vertex;
  uint32_t count; /* 1 to 4 */
  uint32_t from[4];
  double weight[4];
} tetcut_engine_moved_vertex;

/* What the last operation changed, in tet ids of the mesh before it (removed) and after it
   (created; a created tet may reuse a removed id). Vertices are never renumbered. */
typedef struct tetcut_engine_changes {
  const uint32_t* removed;
  uint32_t removed_count;
  const uint32_t* created;
  uint32_t created_count;
  const tetcut_engine_moved_vertex* moved;
  uint32_t moved_count;
  /* TETCUT_ENGINE_TISSUE_RULE: the longest edge the engine lets a tet in the tool keep (tetcut's
     D_ref), and the tets it reports it left in the tool. 0 and none otherwise. */
  double d_ref;
  const uint32_t* left_in_tool;
  uint32_t left_in_tool_count;
  /* TETCUT_ENGINE_QUALITY_FLOOR: nonzero when the engine could not hold this operation's created
     tets to the rule's 15 degree angle floor and held them to angle_floor_deg instead (tetcut goes
     down to 10 degrees, then to none: 0). The harness judges by the lower floor and reports every
     operation that lowered it. 0: the rule's floor held. */
  uint32_t angle_floor_lowered;
  double angle_floor_deg;
} tetcut_engine_changes;

typedef struct tetcut_engine_api {
  uint32_t abi_version;  /* TETCUT_ENGINE_ABI_VERSION the adapter was built with */
  uint32_t capabilities; /* tetcut_engine_capability bits */
  /* Names the adapter in reports and in corpus/regressions/engines/<name>/: [a-z0-9_-], at most
     64 characters. */
  const char* name;
  const char* version;   /* the engine's own version, for people */

  /* Builds an engine on a copy of `mesh` (no tombstones in it). NULL on failure, with one line
     written into error[0 .. error_size). */
  tetcut_engine* (*create)(const tetcut_engine_mesh* mesh, char* error, size_t error_size);
  void (*destroy)(tetcut_engine* engine);

  /* Removes tet `tet` (and whatever else the engine removes or refines to do it). */
  int (*remove_tet)(tetcut_engine* engine, uint32_t tet);
  /* Removes the tissue of a ball: centre[3], diameter > 0. */
  int (*cut_ball)(tetcut_engine* engine, const double* centre, double diameter);
  /* TETCUT_ENGINE_CAPSULE, else NULL: every point within diameter / 2 of the segment a-b. */
  int (*cut_capsule)(tetcut_engine* engine, const double* a, const double* b, double diameter);

  /* The live mesh now, into *out. */
  int (*mesh)(tetcut_engine* engine, tetcut_engine_mesh* out);
  /* TETCUT_ENGINE_CHANGE_LOG, else NULL: what the last operation changed, into *out. */
  int (*changes)(tetcut_engine* engine, tetcut_engine_changes* out);

  /* One line: why the last operation returned TETCUT_ENGINE_ERROR. May be NULL. */
  const char* (*last_error)(tetcut_engine* engine);
} tetcut_engine_api;

/* Every adapter library defines this one function, with C linkage and default visibility. */
#if defined(__GNUC__)
#define TETCUT_ENGINE_EXPORT __attribute__((visibility("default")))
#else
#define TETCUT_ENGINE_EXPORT
#endif
TETCUT_ENGINE_EXPORT const tetcut_engine_api* tetcut_engine_adapter(void);

typedef const tetcut_engine_api* (*tetcut_engine_adapter_fn)(void);

#ifdef __cplusplus
}
#endif

#endif /* TETCUT_HARNESS_ENGINE_H */
