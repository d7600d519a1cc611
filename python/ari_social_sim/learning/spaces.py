"""Box spaces in the Gymnasium convention, for when gymnasium is not installed."""

import numpy as np


class Box:
    """A box of real numbers: every element between `low` and `high` (either may be infinite).

    Mirrors gymnasium.spaces.Box's attributes and methods that training code uses: shape, dtype,
    low, high, sample(), contains() and seed().
    """

    def __init__(self, low, high, shape=None, dtype=np.float32, seed=None):
        self.dtype = np.dtype(dtype)
        if shape is None:
            shape = np.shape(low)
        self.shape = tuple(shape)
        self.low = np.broadcast_to(np.asarray(low, dtype=self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=self.dtype), self.shape).copy()
        self._rng = np.random.default_rng(seed)

    def seed(self, seed=None):
        self._rng = np.random.default_rng(seed)
        return [seed]

    def sample(self):
        """Uniform where both bounds are finite, normal where neither is, exponential from the
        one finite bound otherwise (as gymnasium samples)."""
        low, high = self.low.astype(np.float64), self.high.astype(np.float64)
        sample = np.empty(self.shape)
        bounded = np.isfinite(low) & np.isfinite(high)
        unbounded = ~np.isfinite(low) & ~np.isfinite(high)
        below = np.isfinite(low) & ~np.isfinite(high)
        above = ~np.isfinite(low) & np.isfinite(high)
        sample[bounded] = self._rng.uniform(low[bounded], high[bounded])
        sample[unbounded] = self._rng.normal(size=unbounded.sum())
        sample[below] = low[below] + self._rng.exponential(size=below.sum())
        sample[above] = high[above] - self._rng.exponential(size=above.sum())
        return sample.astype(self.dtype)

    def contains(self, x):
        x = np.asarray(x)
        return (x.shape == self.shape and np.can_cast(x.dtype, self.dtype)
                and bool(np.all(x >= self.low)) and bool(np.all(x <= self.high)))

    def __contains__(self, x):
        return self.contains(x)

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"
