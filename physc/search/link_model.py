"""Where links happen, learned from what the search simulates: the proposal model.

For each kind of link (hit, roll, slide, fall, bounce, ...), the chance that a placed layout
realises it, once the links before it were, as a function of the link's features in that layout
(physc.search.link_features). A compile's placed layouts each teach it: the links its best play
realised in order are examples that happened, the first it did not is one that did not, and the
links after that are not examples (never reached). A layout's chance of realising its chain is the
product of its links' chances; the layout loop tries the likeliest layouts of a pool first
(physc.driver.ranking).

The model of a kind is a logistic regression on the link's features and their pairwise products
and squares (scikit-learn: StandardScaler, PolynomialFeatures(2), LogisticRegression with an L2
penalty). Why this: a link happens in a *region* of its features (a roll needs room to run, but
not so much that the roller stops; a fall needs height) and a quadratic boundary is the least
model that has one; with tens to hundreds of examples, a regularised linear model in those terms
neither overfits nor needs tuning, fits in milliseconds, and its lbfgs solver is deterministic, so
the same examples give the same ranking and the same task. Learned from the compile's own layouts,
from a world's prior (physc.driver.link_prior) whose examples count `PRIOR_WEIGHT` each, and, in
a dataset, from the compiles of its scenario's earlier tasks (physc.dataset.waves), whose examples
count as the compile's own: the prior says where a kind of link happens in general, the
scenario's compiles what happens in that scenario. A kind with examples of one outcome only (or
none) has their share as its chance, with one imagined example of each outcome (Laplace's rule).
"""

from __future__ import annotations

import warnings
from collections.abc import Iterable, Sequence

import attrs
import numpy as np

from physc.search.link_features import LinkFeatures

PRIOR_WEIGHT = 0.25  # what an example of the world's prior counts against one of the compile's own
PENALTY = 0.3  # the logistic regression's inverse regularisation strength (scikit-learn's C)
FLOOR = 0.02  # a link's chance is kept within [FLOOR, 1 - FLOOR]: no layout is ruled out for good

Example = tuple[tuple[float, ...], bool]  # a link's features, and whether it was realised
KindedExample = tuple[str, tuple[float, ...], bool]  # an example with its link's kind


def examples(links: Sequence[LinkFeatures], best: int) -> list[KindedExample]:
    """What one placed layout teaches: (kind, features, realised) of each link up to the first
    its best play did not realise (`best`: the links realised in order)."""
    return [(f.kind, f.values, f.index < best) for f in links if f.index <= best]


def by_kind(rows: Iterable[KindedExample]) -> dict[str, list[Example]]:
    """Examples with their kinds, grouped by kind (in the order given)."""
    grouped: dict[str, list[Example]] = {}
    for kind, values, realised in rows:
        grouped.setdefault(kind, []).append((tuple(values), bool(realised)))
    return grouped


@attrs.define
class LinkModel:
    """The chance of each kind of link, learned (module docstring)."""

    prior: dict[str, list[Example]] = attrs.field(factory=dict)  # a world's, counted PRIOR_WEIGHT each
    own: dict[str, list[Example]] = attrs.field(factory=dict)  # the compile's own
    earlier: dict[str, list[Example]] = attrs.field(factory=dict)  # the scenario's earlier tasks' (a dataset)
    fitted: dict[str, object] = attrs.field(factory=dict)  # kind → a fitted pipeline, or a fixed chance
    stale: bool = True

    def learn(self, links: Sequence[LinkFeatures], best: int) -> None:
        """One placed layout's examples (`examples`), added to the compile's own."""
        for kind, values, realised in examples(links, best):
            self.own.setdefault(kind, []).append((values, realised))
        self.stale = True

    def taught(self) -> list[KindedExample]:
        """The compile's own examples, (kind, features, realised), by kind and in the order learned:
        what a dataset's later tasks learn from (physc.dataset.waves)."""
        return [(kind, values, realised) for kind in sorted(self.own) for values, realised in self.own[kind]]

    @property
    def learned(self) -> int:
        """The compile's own examples so far."""
        return sum(len(rows) for rows in self.own.values())

    def fit(self) -> None:
        """Each kind's model fitted again to the examples it has (only when new ones came)."""
        if not self.stale:
            return
        self.fitted = {
            kind: fitted(self.prior.get(kind, []), self.earlier.get(kind, []) + self.own.get(kind, []))
            for kind in self.kinds()
        }
        self.stale = False

    def kinds(self) -> list[str]:
        return sorted(set(self.prior) | set(self.earlier) | set(self.own))

    def chance(self, links: Iterable[LinkFeatures]) -> float:
        """The chance that a layout with these links realises its chain: the product of each
        link's (a kind never seen: one half)."""
        self.fit()
        chance = 1.0
        for link in links:
            model = self.fitted.get(link.kind)
            if model is None:
                p = 0.5
            elif isinstance(model, float):
                p = model
            else:
                p = float(model.predict_proba(np.array([link.values]))[0, 1])  # type: ignore[attr-defined]
            chance *= min(max(p, FLOOR), 1.0 - FLOOR)
        return chance


def fitted(prior: list[Example], own: list[Example]) -> object:
    """A kind's model: a pipeline fitted to its weighted examples, or (with examples of one
    outcome only) their share by Laplace's rule."""
    rows = prior + own
    weights = np.array([PRIOR_WEIGHT] * len(prior) + [1.0] * len(own))
    outcomes = np.array([realised for _, realised in rows], dtype=int)
    if len(set(outcomes.tolist())) < 2:
        return float((weights @ outcomes + 1.0) / (weights.sum() + 2.0))
    from sklearn.linear_model import LogisticRegression  # imported when a model is first fitted
    from sklearn.pipeline import make_pipeline
    from sklearn.preprocessing import PolynomialFeatures, StandardScaler

    model = make_pipeline(StandardScaler(), PolynomialFeatures(2), LogisticRegression(C=PENALTY, max_iter=2000))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # a solver that stops early still ranks
        model.fit(np.array([values for values, _ in rows]), outcomes, logisticregression__sample_weight=weights)
    return model
