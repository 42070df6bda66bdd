"""Interleaved side-by-side timing for the compare_*.py scripts (issue 19, items 1 and 6).

The development machine is shared by several jobs, so a time measured at one moment and a time
measured a minute later are not comparable: the load changes between them. Here every round
times each contender once, back to back (the order alternating from round to round, so that
neither always runs on the caches or the turbo budget the other left), and a ratio is formed
within each round. The figures reported are the median of the per-round times and of the
per-round ratios, with their spread (min-max and the interquartile range), never one best run.
"""
import time


def seconds(f):
    """Wall time of one call of f (and its result)."""
    start = time.perf_counter()
    result = f()
    return time.perf_counter() - start, result


def median_of(f, inner):
    """The median wall time of `inner` calls of f (and the last result): one measurement of a
    contender that takes about a millisecond, where a single call would be timer and scheduler
    noise. The C++ drivers report the median of their own repeats in the same way."""
    times, result = [], None
    for _ in range(max(1, inner)):
        t, result = seconds(f)
        times.append(t)
    return quantiles(times)[0], result


def quantiles(values):
    """(median, q1, q3, min, max) of a non-empty list, with linear interpolation."""
    v = sorted(values)

    def q(p):
        x = p * (len(v) - 1)
        i = int(x)
        return v[i] if i + 1 >= len(v) else v[i] + (x - i) * (v[i + 1] - v[i])
    return q(0.5), q(0.25), q(0.75), v[0], v[-1]


class Rounds:
    """Times of named contenders over interleaved rounds.

    `contenders` maps a name to a callable that returns the seconds of one measurement (it may
    time itself, as the C++ drivers do, or be wrapped by `seconds`/`median_of`)."""

    def __init__(self, contenders):
        self.names = list(contenders)
        self.contenders = contenders
        self.times = {name: [] for name in self.names}

    def run(self, rounds):
        for r in range(rounds):
            order = self.names if r % 2 == 0 else list(reversed(self.names))
            for name in order:
                self.times[name].append(self.contenders[name]())
        return self

    def median(self, name):
        return quantiles(self.times[name])[0]

    def ratios(self, slower, faster):
        """Per-round ratios slower/faster: how many times faster `faster` was in each round."""
        return [a / b for a, b in zip(self.times[slower], self.times[faster])]

    def describe_time(self, name, unit=1e-3, label="ms"):
        m, q1, q3, lo, hi = quantiles(self.times[name])
        return (f"{m / unit:9.3f} {label} (IQR {q1 / unit:.3f}-{q3 / unit:.3f}, "
                f"range {lo / unit:.3f}-{hi / unit:.3f})")

    def describe_ratio(self, slower, faster):
        m, q1, q3, lo, hi = quantiles(self.ratios(slower, faster))
        return f"{m:7.2f}x (IQR {q1:.2f}-{q3:.2f}, range {lo:.2f}-{hi:.2f}, {len(self.times[slower])} rounds)"
