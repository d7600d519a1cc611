#!/usr/bin/env bash
# Installs every Debian bookworm package ari_social_sim needs to build, run, test and be looked at.
# Safe to run again: apt-get skips what is already there.
set -euo pipefail

packages=(
  # build
  build-essential cmake ccache catkin python3-catkin-pkg ros-core-dev ros-base-dev
  # ROS runtime and tools a user reaches for
  rosbash python3-roslaunch python3-rostest librostest-dev python3-rosbag python3-rostopic
  python3-rosservice python3-rosnode python3-rosparam python3-rosmsg python3-rosgraph
  ros-robot-state-publisher tf2-tools python3-tf2-ros libtf2-ros-dev libtf2-geometry-msgs-dev
  libactionlib-dev python3-actionlib libmove-base-msgs-dev python3-move-base-msgs
  librosbag-dev
  python3-std-msgs python3-geometry-msgs python3-nav-msgs python3-sensor-msgs
  python3-visualization-msgs python3-actionlib-msgs python3-rosgraph-msgs python3-std-srvs
  python3-trajectory-msgs python3-rospy python3-diagnostic-msgs
  libstd-srvs-dev
  # simulation cores
  libbox2d-dev libbullet-dev libeigen3-dev libyaml-cpp-dev libopencv-dev liboctomap-dev libnlopt-dev
  liburdfdom-dev liburdfdom-tools
  # headless camera rendering: OpenGL through EGL, Mesa's llvmpipe when there is no GPU
  libegl-dev libgl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri
  # Python bindings of the learning environments (ari_social_sim.learning)
  pybind11-dev python3-dev python3-numpy
  # tests and benchmarks; opencv-data holds the stock Haar cascades the detector study runs
  python3-pytest opencv-data
  # scripts/fetch_data.sh: downloads the public data sets and reads the F-formation recordings'
  # MATLAB files (docs/data.md)
  curl python3-scipy
  libgtest-dev googletest libbenchmark-dev
  # the habits scripts/test.sh enforces: formatting (check_format.sh) and clang_tidy.sh, which
  # asks git for the sources a change touches
  clang-format-14 clang-tidy-14 git
  # audio (docs/audio.md): voices synthesised with libespeak-ng, speech recognised with
  # pocketsphinx and its US English model, audio data sets written with libsndfile
  libespeak-ng-dev libpocketsphinx-dev libsphinxbase-dev pocketsphinx-en-us libsndfile1-dev
  # inspection (sox reads, plays and draws the audio files, scripts/draw_audio.py writes its
  # labels in DejaVu; espeak-ng speaks a voice to try it)
  rviz xvfb xauth imagemagick sox espeak-ng fonts-dejavu-core
  # rsvg-convert renders docs/architecture.svg to look at (ImageMagick reads no SVG without it)
  librsvg2-bin
  # batch work and training on a SLURM cluster (issue 32): the tests start a single-host cluster
  # of these daemons, each on ports and folders of its own (munge authenticates the daemons)
  slurmctld slurmd slurm-client munge
)

installer=install_deps
source "$(dirname "$0")/apt_install.sh"
