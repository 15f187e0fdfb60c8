"""The quantile every latency in the tables is quoted with (standard library only)."""


def percentile(values, q):
    """The q-quantile of `values` with linear interpolation between the sorted values, as
    report::Percentile computes summary.csv's (latency_med, latency_p90); None if there are none."""
    values = sorted(values)
    if not values:
        return None
    position = q * (len(values) - 1)
    i = int(position)
    return values[i] + (position - i) * (values[i + 1] - values[i]) if i + 1 < len(values) else values[i]


def latency_text(latencies):
    """A table's latency cell, "1.65x (2.31x)": the median (90th percentile), as summary.md writes
    it (report::LatencyCell); None where there are none."""
    if not latencies:
        return None
    return f"{percentile(latencies, 0.5):.2f}x ({percentile(latencies, 0.9):.2f}x)"
