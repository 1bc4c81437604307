"""rodyn's rigid-body dynamics on numpy arrays, in Pinocchio's conventions.

Arrays in: contiguous float64 numpy arrays are read in place; sequences of
numbers and strided float64 arrays are copied; other dtypes raise
ValueError. Arrays out: new float64 arrays, or the `out=` buffer given
(float64, C-contiguous, writable, the result's shape), which is returned.
"""

from os import PathLike
from typing import Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

Vector = Union[npt.NDArray[np.float64], Sequence[float]]
Contact = Union[str, Tuple[str, str]]

class ModelError(ValueError):
    """A model file rodyn cannot build a model from."""

    file: str
    line: int
    column: int
    message: str

class Model:
    @staticmethod
    def from_urdf(path: Union[str, PathLike[str]], floating_base: bool = False) -> Model: ...
    @staticmethod
    def from_file(path: Union[str, PathLike[str]]) -> Model: ...
    @property
    def nq(self) -> int: ...
    @property
    def nv(self) -> int: ...
    @property
    def joint_names(self) -> list[str]: ...
    @property
    def frame_names(self) -> list[str]: ...
    @property
    def warnings(self) -> list[str]: ...
    def neutral(self) -> npt.NDArray[np.float64]: ...
    def random_configuration(self, seed: Optional[int] = None) -> npt.NDArray[np.float64]: ...
    def rnea(self, q: Vector, v: Vector, a: Vector, *, out: Optional[npt.NDArray[np.float64]] = None) -> npt.NDArray[np.float64]: ...
    def aba(self, q: Vector, v: Vector, tau: Vector, *, out: Optional[npt.NDArray[np.float64]] = None) -> npt.NDArray[np.float64]: ...
    def crba(self, q: Vector, *, out: Optional[npt.NDArray[np.float64]] = None) -> npt.NDArray[np.float64]: ...
    def gravity(self, q: Vector) -> npt.NDArray[np.float64]: ...
    def nonlinear_effects(self, q: Vector, v: Vector) -> npt.NDArray[np.float64]: ...
    def frame_placement(self, q: Vector, name: str) -> npt.NDArray[np.float64]: ...
    def frame_jacobian(
        self,
        q: Vector,
        name: str,
        reference: str = "local_world_aligned",
        *,
        out: Optional[npt.NDArray[np.float64]] = None,
    ) -> npt.NDArray[np.float64]: ...
    def com(self, q: Vector) -> npt.NDArray[np.float64]: ...
    def centroidal_map(self, q: Vector) -> npt.NDArray[np.float64]: ...
    def rnea_derivatives(
        self, q: Vector, v: Vector, a: Vector
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def aba_derivatives(
        self, q: Vector, v: Vector, tau: Vector
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def constrained_dynamics(
        self, q: Vector, v: Vector, tau: Vector, contacts: Sequence[Contact]
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def kinetic_energy(self, q: Vector, v: Vector) -> float: ...
    def potential_energy(self, q: Vector) -> float: ...
    def frame_jacobian_time_variation(
        self,
        q: Vector,
        v: Vector,
        name: str,
        reference: str = "local_world_aligned",
        *,
        out: Optional[npt.NDArray[np.float64]] = None,
    ) -> npt.NDArray[np.float64]: ...
    def impulse_dynamics(
        self, q: Vector, v: Vector, contacts: Sequence[Contact], restitution: float = 0.0
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def integrate(self, q: Vector, v: Vector) -> npt.NDArray[np.float64]: ...
    def inverse_kinematics(
        self,
        name: str,
        target: npt.ArrayLike,
        q0: Vector,
        tolerance: float = 1e-10,
        max_iterations: int = 100,
    ) -> npt.NDArray[np.float64]: ...
