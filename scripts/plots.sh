#!/usr/bin/env bash
# Regenerates every figure from the CSV files in results/ (Debian's matplotlib: /usr/bin/python3).
set -euo pipefail
cd "$(dirname "$0")/../plot_scripts"
for script in table1_bars.py error_vs_crlb.py bias_aware.py sweep_pdop_threshold.py sweep_tau.py sweep_noise_outliers.py \
  pdop_fig6.py pdop_triggers.py halls.py table2.py credibility.py calibration_cells.py navigation.py; do
  /usr/bin/python3 "$script"
done
