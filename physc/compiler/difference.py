"""Systems of difference constraints  x_v − x_u ≤ w, kept as all-pairs shortest paths.

The constraint graph has an edge u → v of weight w for each constraint. The system
is consistent exactly when the graph has no negative cycle, and then the shortest
path distance d(u, v) is the largest value x_v − x_u can take. Variable 0 is the
origin (the value 0), so each variable v ranges over [−d(v, 0), d(0, v)], and any
value in that interval extends to a solution of the whole system.

Adding one constraint updates the distance matrix in O(n²) (numpy), and copying a
system is cheap, which is what a backtracking search over conjunctions needs.
"""

from __future__ import annotations

import numpy as np

TOLERANCE = 1e-9


class Inconsistent(Exception):
    """Adding a constraint closed a negative cycle."""

    def __init__(self, cycle_weight: float):
        super().__init__(f"negative cycle of weight {cycle_weight:.6g}")
        self.cycle_weight = cycle_weight


class DifferenceSystem:
    def __init__(self, names: list[str]):
        self.names = list(names)
        self.index = {name: i for i, name in enumerate(self.names)}
        n = len(self.names)
        self.dist = np.full((n, n), np.inf)
        np.fill_diagonal(self.dist, 0.0)

    def copy(self) -> DifferenceSystem:
        other = DifferenceSystem.__new__(DifferenceSystem)
        other.names = self.names
        other.index = self.index
        other.dist = self.dist.copy()
        return other

    def add(self, u: str, v: str, weight: float) -> None:
        """Add x_v − x_u ≤ weight; raise Inconsistent (leaving self unchanged) if it cannot hold."""
        i, j = self.index[u], self.index[v]
        back = self.dist[j, i]
        if back + weight < -TOLERANCE:
            raise Inconsistent(back + weight)
        if weight >= self.dist[i, j]:
            return
        through = self.dist[:, i : i + 1] + weight + self.dist[j : j + 1, :]
        np.minimum(self.dist, through, out=self.dist)

    def add_all(self, constraints) -> None:
        for u, v, weight in constraints:
            self.add(u, v, weight)

    def fix(self, v: str, value: float) -> None:
        """Add x_v = value."""
        self.add("0", v, value)
        self.add(v, "0", -value)

    def bounds(self, v: str) -> tuple[float, float]:
        i, o = self.index[v], self.index["0"]
        return -self.dist[i, o], self.dist[o, i]
