#!/usr/bin/env bash
# docs/figures/opensim_overlay.png: bench/peers/plot_overlay.sh's OpenSim case, by its
# earlier name.
#   bash bench/peers/plot_opensim_overlay.sh [BUILD_DIR]
exec bash "$(dirname "$0")/plot_overlay.sh" opensim "$@"
