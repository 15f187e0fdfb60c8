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
