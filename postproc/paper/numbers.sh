#!/bin/sh
# The numbers behind doc/reproduction.md, from the runs of tools/paper-figures.sh.
#
#   sh postproc/paper/numbers.sh RUNS [CCX_FILE] > numbers.txt
#
# RUNS holds <deck>/<deck>.contact1.txt and .history.txt. Every profile
# figure is taken at result frame 20 (t = T, maximum indentation). Normal
# stress: lambda_n (column 9) for mortar, 'pressure' (column 5) for
# node-to-segment and in the cross-method table; compressive positive.
# Differences between two profiles on different nodes: the second is
# interpolated linearly in the deformed x at the nodes of the first, both
# ways, and the largest |difference| is divided by the larger peak. 'inner'
# restricts the nodes to |x| < 0.8 of the contact half-width (away from the
# contact edges, where one node spacing of edge position is a difference of
# order the peak by itself). POSIX sh + awk + sort only.
set -eu
runs=$1
ccx=${2:-}
frame=20

. "$(dirname "$0")/numbers-lib.sh"

echo "# raccord: numbers of doc/reproduction.md (postproc/paper/numbers.sh), frame $frame (t = T)"
echo
echo "## 1. Peak, contact width (x extent of the active slave nodes), integral of the stress over x"
echo "## normal stress: pressure (col 5) for node-to-segment, lambda_n (col 9) for mortar"
stats fig1b_nts_slave_block 5
stats fig1b_nts_slave_disc 5
for n in fig2a_mortar_p1_slave_block fig2a_mortar_p1_slave_disc fig2b_mortar_p0_slave_block fig2b_mortar_p0_slave_disc \
         fig4a_q4_mortar_p1 fig4a_q8_mortar_p1; do
  stats $n 9
done
echo
echo "## 2. Slave/master asymmetry: slave = block against slave = disc, max |dp| / p_max"
diff2 fig1b_nts_slave_block 5 fig1b_nts_slave_disc 5 "node-to-segment, pressure"
diff2 fig2a_mortar_p1_slave_block 9 fig2a_mortar_p1_slave_disc 9 "mortar P1, lambda_n"
diff2 fig2a_mortar_p1_slave_block 5 fig2a_mortar_p1_slave_disc 5 "mortar P1, pressure"
diff2 fig2b_mortar_p0_slave_block 9 fig2b_mortar_p0_slave_disc 9 "mortar P0, lambda_n"
echo
echo "## 3. P0 against P1 (same slave, same nodes), max |dlambda_n| / p_max"
diff2 fig2a_mortar_p1_slave_block 9 fig2b_mortar_p0_slave_block 9 "mu = 0, slave = block"
diff2 fig2a_mortar_p1_slave_disc 9 fig2b_mortar_p0_slave_disc 9 "mu = 0, slave = disc"
for mu in 010 020 050; do
  diff2 fig3_mortar_p1_mu$mu 9 fig3_mortar_p0_mu$mu 9 "mu = $mu (/100), normal"
  diff2 fig3_mortar_p1_mu$mu 10 fig3_mortar_p0_mu$mu 10 "mu = $mu (/100), tangential lambda_t"
done
diff2 fig4b_q8_mortar_p1_mu020 9 fig4b_q8_mortar_p0_mu020 9 "Q8, mu = 0.2, normal"
echo
echo "## 4. Q1 against Q2 (paper_q4 / paper_q8, mortar P1), max |dlambda_n| / p_max"
diff2 fig4a_q4_mortar_p1 9 fig4a_q8_mortar_p1 9 "Q4 / Q8, lambda_n"
echo
echo "## 5. Friction: Coulomb cone and stick/slip zones (status column: 1 stick, 2 slip)"
for mu in 010 020 050; do
  m=$(awk -v m=$mu 'BEGIN { print m / 100 }')
  stats fig3_mortar_p1_mu$mu 9 $m
  stats fig3_mortar_p0_mu$mu 9 $m
done
stats fig4b_q8_mortar_p1_mu020 9 0.2
stats fig4b_q8_mortar_p0_mu020 9 0.2
echo "## status column at frame 10 (t = T/2, fastest loading) and frame 20 (t = T, the load at rest: no increment, so little slips)"
for n in fig3_mortar_p1_mu010 fig3_mortar_p1_mu020 fig3_mortar_p1_mu050 fig3_mortar_p0_mu020 fig4b_q8_mortar_p1_mu020; do
  status_at $n 10; status_at $n 20
done
echo
echo "## 6. Method against method (pressure, col 5; slave = block)"
diff2 fig2a_mortar_p1_slave_block 5 fig1b_nts_slave_block 5 "mortar P1 / node-to-segment"
diff2 fig2a_mortar_p1_slave_block 9 fig3_mortar_p1_mu020 9 "mu = 0 / mu = 0.2 (P1, lambda_n)"
if [ -n "$ccx" ] && [ -s "$ccx" ]; then
  echo
  echo "## 7. CalculiX (node-to-surface, slave = block, $(basename "$ccx")) against raccord node-to-segment, slave = block"
  awk 'BEGIN { pk = 0 } !/^#/ && NF >= 2 { n++; if ($2 > pk) { pk = $2; xp = $1 } if ($2 > 0) { if (!l || $1 < xl) { xl = $1; l = 1 } if (!r || $1 > xr) { xr = $1; r = 1 } } }
       END { printf "%-34s peak %8.1f MPa at x = %+.4f  x in [%+.4f, %+.4f], width %.4f mm\n", "calculix", pk, xp, xl, xr, xr - xl }' "$ccx"
  mkdir -p "$runs/ccx" && awk '!/^#/ && NF >= 2 { printf "0 %s 0 0 %s 0 %d 0 %s 0\n", $1, $2, ($2 > 0), $2 }' "$ccx" > "$runs/ccx/ccx.contact1.txt.tmp"
  { echo "# frame $frame  time 0"; cat "$runs/ccx/ccx.contact1.txt.tmp"; } > "$runs/ccx/ccx.contact1.txt"; rm -f "$runs/ccx/ccx.contact1.txt.tmp"
  diff2 fig1b_nts_slave_block 5 ccx 5 "raccord NTS slave = block / CalculiX"
  diff2 fig1b_nts_slave_disc 5 ccx 5 "raccord NTS slave = disc / CalculiX"
  diff2 fig2a_mortar_p1_slave_block 9 ccx 5 "raccord mortar P1 slave = block / CalculiX"
fi
echo
echo "## 8. Quasi-static evidence: energies and forces at t = T; T doubled (slow_*)"
for n in fig1b_nts_slave_block fig1b_nts_slave_disc fig2a_mortar_p1_slave_block fig2a_mortar_p1_slave_disc \
         fig2b_mortar_p0_slave_block fig3_mortar_p1_mu020 fig4a_q8_mortar_p1 \
         slow_fig2a_mortar_p1_slave_block slow_fig3_mortar_p1_mu020; do
  hist_at $n
done
ke_ie_max fig2a_mortar_p1_slave_block
ke_ie_max slow_fig2a_mortar_p1_slave_block
diff2 fig2a_mortar_p1_slave_block 9 slow_fig2a_mortar_p1_slave_block 9 "T / 2T, mortar P1 mu = 0, lambda_n"
diff2 fig3_mortar_p1_mu020 9 slow_fig3_mortar_p1_mu020 9 "T / 2T, mortar P1 mu = 0.2, lambda_n"
diff2 fig3_mortar_p1_mu020 10 slow_fig3_mortar_p1_mu020 10 "T / 2T, mortar P1 mu = 0.2, lambda_t"
force_diff fig2a_mortar_p1_slave_block slow_fig2a_mortar_p1_slave_block
force_diff fig3_mortar_p1_mu020 slow_fig3_mortar_p1_mu020
