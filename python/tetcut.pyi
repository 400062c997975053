"""tetcut: manifold-preserving tissue removal on tetrahedral meshes (Forest, Delingette, Ayache 2002).

Hand-written stub of the pybind11 module (python/src/); ctest python.stubtest holds it to the
module with mypy's stubtest. Shapes as the docs write them: "#T by 4".
"""
from typing import Any, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

_Point = Union[Sequence[float], npt.ArrayLike]

class _SlotViewLock:
    """Keeps a mesh alive and unchanged while a slot view of it exists (internal)."""

class Mesh:
    """A manifold tetrahedral mesh, validated when made.

    Mesh(points, tets, labels=None, *, drop_unused_points=False): points #V by 3 (any real
    array-like), tets #T by 4 (integer vertex indices, 0-based, positively oriented), labels #T
    integers in 0..2^31-1 or None, all copied. Points no tet uses are refused (ValueError naming
    them) unless dropped. ValueError with the message `tetcut` prints for what it refuses (NaN,
    dangling or repeated indices, inverted tets, non-manifold input); ValueError / TypeError for a
    wrong shape or dtype. Index arrays are int64 but for the slot views (uint32). Copyable and
    picklable (a pickled mesh comes back with dense ids).
    """

    def __init__(
        self, points: npt.ArrayLike, tets: npt.ArrayLike, labels: npt.ArrayLike | None = None, *, drop_unused_points: bool = False
    ) -> None: ...
    @property
    def num_tets(self) -> int: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def points(self) -> npt.NDArray[np.float64]:
        """#V by 3: the live vertices in id order (a copy), as the last change that returned left them:
        never refused while another thread cuts."""
    @property
    def vertex_ids(self) -> npt.NDArray[np.int64]:
        """#V: the engine id of each row of `points`."""
    @property
    def tets(self) -> npt.NDArray[np.int64]:
        """#T by 4: the live tets in id order, as rows of `points` (a copy)."""
    @property
    def tet_ids(self) -> npt.NDArray[np.int64]:
        """#T: the engine id of each row of `tets`."""
    @property
    def labels(self) -> npt.NDArray[np.int64] | None:
        """#T: each tet's label, rows as `tets` (a copy), carried through cuts; None if unlabelled; never refused during another thread's cut."""
    @property
    def slot_tets(self) -> npt.NDArray[np.uint32]:
        """Slots by 4 uint32 (0xFFFFFFFF in column 0: a removed tet), read-only, no copy; locks the mesh while alive."""
    @property
    def slot_points(self) -> npt.NDArray[np.float64]:
        """Vertex slots by 3, read-only, no copy; locks the mesh like slot_tets."""
    @property
    def live_tet_mask(self) -> npt.NDArray[np.bool_]: ...
    @property
    def live_vertex_mask(self) -> npt.NDArray[np.bool_]: ...
    @property
    def attribute_names(self) -> list[str]: ...
    def surface(self) -> npt.NDArray[np.int64]:
        """#F by 3: boundary triangles as rows of `points`, counter-clockwise seen from outside."""
    def volume(self) -> float: ...
    def hash(self) -> str:
        """The canonical hash `tetcut` prints (16 hex digits)."""
    def vertex_attribute(self, name: str) -> npt.NDArray[np.float64]:
        """#V (a channel set from #V values) or #V by width, rows as `points` (a copy)."""
    def set_vertex_attribute(self, name: str, values: npt.ArrayLike) -> None: ...
    def write(self, path: str, *, binary: bool = False, compression: str = "none") -> None: ...
    def compact(self, order: str = "curve") -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]:
        """(tet_old_to_new, vertex_old_to_new), -1 for a removed id; new ids along a space-filling
        curve ('curve') or in their old relative order ('kept')."""
    def to_meshio(self) -> Any:
        """A meshio.Mesh: points, one 'tetra' block, attributes as point_data, labels as cell_data 'label'."""
    def copy(self) -> Mesh:
        """An independent copy: same ids, points, tets, labels and attributes."""
    def __copy__(self) -> Mesh: ...
    def __deepcopy__(self, memo: Any) -> Mesh: ...
    def __getstate__(self) -> tuple[Any, ...]: ...
    def __setstate__(self, state: tuple[Any, ...]) -> None: ...

def read(path: str) -> Mesh:
    """Reads and builds a mesh file; ValueError with the line `tetcut` prints."""

def from_meshio(mesh: Any, *, drop_unused_points: bool = False) -> Mesh:
    """A Mesh from a meshio.Mesh's points, 'tetra' cells, real point_data and integer cell_data labels."""

class Changes:
    """A cut's net change as numpy arrays of engine ids."""

    @property
    def removed(self) -> npt.NDArray[np.int64]: ...
    @property
    def created(self) -> npt.NDArray[np.int64]: ...
    @property
    def parent(self) -> npt.NDArray[np.int64]: ...
    @property
    def parents(self) -> npt.NDArray[np.int64]: ...
    @property
    def parents_offsets(self) -> npt.NDArray[np.int64]: ...
    @property
    def new_vertices(self) -> npt.NDArray[np.int64]: ...
    @property
    def new_vertex_edges(self) -> npt.NDArray[np.int64]: ...
    @property
    def new_vertex_t(self) -> npt.NDArray[np.float64]: ...
    @property
    def new_vertex_from(self) -> npt.NDArray[np.int64]: ...
    @property
    def new_vertex_weights(self) -> npt.NDArray[np.float64]: ...
    @property
    def removed_vertices(self) -> npt.NDArray[np.int64]: ...
    @property
    def moved_vertices(self) -> npt.NDArray[np.int64]: ...
    @property
    def moved_vertex_from(self) -> npt.NDArray[np.int64]: ...
    @property
    def moved_vertex_weights(self) -> npt.NDArray[np.float64]: ...
    @property
    def moved_vertex_before(self) -> npt.NDArray[np.float64]: ...
    @property
    def undo(self) -> bool:
        """True for Cutter.undo()'s: removed are the tets the cut made, created the tets it took, back."""

class Fragment:
    """A piece a cut detached from the organ, copied when the cut returned."""

    @property
    def tets(self) -> npt.NDArray[np.int64]:
        """#P: the piece's tets (engine ids, sorted), a new array on each access."""
    @property
    def volume(self) -> float: ...
    @property
    def centroid(self) -> list[float]: ...
    @property
    def removed(self) -> bool:
        """Removed as debris (below the Cutter's debris_volume)."""
    @property
    def organ(self) -> int:
        """A live tet of the piece it came away from."""

class CutReport:
    """What one cut did; `changes` builds numpy arrays on first access."""

    @property
    def centre(self) -> list[float]: ...
    @property
    def end(self) -> list[float] | None:
        """A capsule's other end (cut_segment, a swept sweep); None for a ball."""
    @property
    def ok(self) -> bool: ...
    @property
    def failure(self) -> str: ...
    @property
    def refusal(self) -> str: ...
    @property
    def tets_hit(self) -> int: ...
    @property
    def refine_iterations(self) -> int: ...
    @property
    def edges_split(self) -> int: ...
    @property
    def tets_refined(self) -> int: ...
    @property
    def requested(self) -> int: ...
    @property
    def requests(self) -> int: ...
    @property
    def tets_removed(self) -> int: ...
    @property
    def tets_created(self) -> int: ...
    @property
    def direct(self) -> int: ...
    @property
    def vertex_singularities(self) -> int: ...
    @property
    def edge_singularities(self) -> int: ...
    @property
    def resolved_by_neighbours(self) -> int: ...
    @property
    def resolved_by_refinement(self) -> int: ...
    @property
    def resolved_by_fallback(self) -> int: ...
    @property
    def unresolved(self) -> int: ...
    @property
    def stopped_by_budget(self) -> int: ...
    @property
    def kept_pieces_requested(self) -> int: ...
    @property
    def left_in_tool(self) -> int: ...
    @property
    def volume_left_in_tool(self) -> float: ...
    @property
    def volume_removed(self) -> float: ...
    @property
    def tets_removed_beyond_tool(self) -> int: ...
    @property
    def volume_removed_beyond_tool(self) -> float: ...
    @property
    def tets_removed_beyond_reach(self) -> int: ...
    @property
    def uncuttable_in_tool(self) -> int: ...
    @property
    def min_radius_ratio(self) -> float: ...
    @property
    def min_radius_ratio_before_improvement(self) -> float: ...
    @property
    def min_dihedral_deg(self) -> float: ...
    @property
    def min_dihedral_deg_before_improvement(self) -> float: ...
    @property
    def quality_floor(self) -> float: ...
    @property
    def dihedral_floor_deg(self) -> float: ...
    @property
    def min_dihedral_held_deg(self) -> float: ...
    @property
    def angle_retries(self) -> int: ...
    @property
    def quality_met(self) -> bool: ...
    @property
    def improvement_flips(self) -> int: ...
    @property
    def improvement_collapses(self) -> int: ...
    @property
    def improvement_moves(self) -> int: ...
    @property
    def vertices_moved(self) -> int: ...
    @property
    def mesh_rule_retries(self) -> int: ...
    @property
    def improvement_insertions(self) -> int: ...
    @property
    def tets_removed_by_improvement(self) -> int: ...
    @property
    def fragments(self) -> int: ...
    @property
    def fragment_tets_visited(self) -> int: ...
    @property
    def fragment_search_bounded(self) -> bool: ...
    @property
    def debris_pieces_removed(self) -> int: ...
    @property
    def debris_tets_removed(self) -> int: ...
    @property
    def debris_volume_removed(self) -> float: ...
    @property
    def d_ref(self) -> float: ...
    @property
    def refinement(self) -> str: ...
    @property
    def retries(self) -> int: ...
    @property
    def wall_us(self) -> float:
        """Wall time of the engine's cut alone, timed around the C++ call."""
    @property
    def time_us(self) -> dict[str, float]: ...
    @property
    def changes(self) -> Changes: ...
    @property
    def detached(self) -> list[Fragment]:
        """The pieces this cut detached (len == fragments), those removed as debris included."""

class Cutter:
    """The cautery tool on a mesh: indexes it once, then cuts in O(tool). Keeps the mesh alive."""

    def __init__(
        self,
        mesh: Mesh,
        *,
        tool_diameter: float,
        strategy: str = "combined",
        split: str = "templates",
        order: str = "direct-first",
        neighbour_set: str = "smallest",
        refinement: str = "auto",
        d_ref_factor: float = 1.5,
        p: float = 1.5,
        search_depth: int = 10,
        max_refine_iterations: int = 8,
        max_tets_created: int = 20000,
        improve: bool = True,
        quality_floor: float = 0.1,
        min_dihedral_deg: float = 15.0,
        debris_volume: float = 0.0,
        fragment_search_bound: int = 65536,
        keep_labels: Sequence[int] = (),
        undo_history: int = 0,
    ) -> None: ...
    def cut(self, centre: _Point) -> CutReport:
        """One atomic cut (ok False: refused, the mesh untouched). Releases the GIL."""
    def cut_segment(self, a: _Point, b: _Point) -> CutReport:
        """One atomic cut by the capsule the tool sweeps from a to b; cut_segment(c, c) is cut(c)."""
    def sweep(self, start: _Point, end: _Point, step: float, swept: bool = False) -> list[CutReport]:
        """One cut every `step` from start to end (end included within a billionth of a step), as `tetcut cut`;
        swept=True joins those centres by capsules (cut_segment from each to the next), as `tetcut cut --swept`."""
    @property
    def tool_diameter(self) -> float: ...
    @tool_diameter.setter
    def tool_diameter(self, value: float) -> None: ...
    @property
    def strategy(self) -> str: ...
    @property
    def mesh(self) -> Mesh: ...
    def last_fragments(self) -> list[Fragment]:
        """The pieces the last cut detached (report.detached of that cut)."""
    @property
    def pieces(self) -> int:
        """The mesh's face-connected pieces, kept by every cut without a scan."""
    def undo(self) -> Changes:
        """Takes back the last cut kept (undo_history), the mesh bit for bit; RuntimeError when none is kept."""
    @property
    def undo_depth(self) -> int: ...
    @property
    def undo_history(self) -> int: ...
    @undo_history.setter
    def undo_history(self, value: int) -> None: ...

class Violation:
    """One violated invariant."""

    @property
    def id(self) -> str: ...
    @property
    def name(self) -> str: ...
    @property
    def count(self) -> int: ...
    @property
    def tets(self) -> npt.NDArray[np.int64]: ...
    @property
    def vertices(self) -> npt.NDArray[np.int64]: ...
    @property
    def detail(self) -> str: ...

def check(mesh: Mesh, *, level: str = "full", radius_ratio_floor: float = 0.0) -> list[Violation]:
    """The independent checker's violations (empty: valid); level local|full|exact."""

def check_engine(
    engine: str,
    *,
    scenarios: Sequence[str] | None = None,
    meshes: Sequence[str] | None = None,
    sweeps: int = 1,
    cuts: int = 24,
    seed: int = 1,
    timeout: int = 600,
) -> list[dict[str, Any]]:
    """Any engine's adapter (engine.h) under the checker: one dict per plan, each run in a child."""

def stats(cutter: Cutter) -> dict[str, dict[str, float]]:
    """The paper's Tables 1 and 2 over a Cutter's removal requests."""
