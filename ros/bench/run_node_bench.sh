#!/usr/bin/env bash
# The node's latency and throughput on one core: a ROS master on a free loopback port, the node
# pinned to core 0, corridor_node_bench (the camera and the consumer) pinned to core 1.
#   ros/bench/run_node_bench.sh BUILD_DIR SCENE_DIR [RATE_HZ] [PASSES]
# SCENE_DIR: a corridor_synth scene (rgb/, camera.yaml), e.g. from
#   corridor_synth --preset=sequence --frames=90 --output_dir=/tmp/bench  ->  /tmp/bench/corridor
# RATE_HZ 0 (default) = lockstep. Prints corridor_node_bench's summary.
set -euo pipefail
BUILD=$1 SCENE=$2 RATE=${3:-0} PASSES=${4:-5}
WORK=$(mktemp -d)
PORT=$(python3 -c "import socket; s=socket.socket(); s.bind(('127.0.0.1',0)); print(s.getsockname()[1])")
export ROS_MASTER_URI=http://127.0.0.1:$PORT ROS_IP=127.0.0.1 ROS_HOME=$WORK ROS_LOG_DIR=$WORK
HEIGHT=$(sed -n 's/^camera_height: *//p' "$SCENE/camera.yaml")
rosmaster --core -p "$PORT" > "$WORK/master.log" 2>&1 &
MASTER=$!
cleanup() {
  kill -INT "${NODE:-}" 2>/dev/null || true
  kill -TERM "$MASTER" 2>/dev/null || true  # A background rosmaster ignores SIGINT.
  wait || true
  rm -rf "$WORK"
}
trap cleanup EXIT
sleep 2
taskset -c 0 "$BUILD/ros/corridor_depth_node" __name:=corridor_depth __ns:=/cd \
  image:=/cam/image_raw _camera_height:="$HEIGHT" _diagnostics_period:=0.5 > "$WORK/node.log" 2>&1 &
NODE=$!
sleep 1
taskset -c 1 "$BUILD/ros/corridor_node_bench" "$SCENE" "$RATE" "$PASSES"
