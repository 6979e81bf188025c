#!/bin/sh
# Python packages for the offline training scripts under bench/ (session 28:
# bench/completion/train_join_cnn.py). Never needed by the build or `make test`.
set -eu
apt-get update
apt-get install -y --no-install-recommends python3-torch python3-numpy
