#!/usr/bin/env bash
# Installs the optional extras that the main set-up leaves out: PyTorch, matplotlib and OpenBLAS
# for the training example (scripts/train_join_group.py, docs/learning.md). About 1 GB; run it as
# root only when you want to train.
set -euo pipefail

packages=(
  python3-torch python3-matplotlib
  # An optimised BLAS: Debian's PyTorch calls the system's libblas.so.3, which without it is the
  # reference implementation, about 25 times slower at the network's matrix products.
  libopenblas0-pthread
)

installer=install_extras
source "$(dirname "$0")/apt_install.sh"
