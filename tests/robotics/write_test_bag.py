#!/usr/bin/python3
"""Writes a ROS 1 bag with the real rosbag library (Debian's python3-rosbag), for the bag tests.

Usage: write_test_bag.py MANIFEST.json OUT.bag
The manifest is a list of messages, in write order:
  {"topic": "/cam/image_raw", "kind": "image", "stamp": [sec, nsec], "frame_id": "cam",
   "encoding": "rgb8", "width": W, "height": H, "step": S, "data_file": "frame0.raw"}
  {"topic": "/cam/image_raw/compressed", "kind": "compressed", "stamp": [...], "format": "jpeg",
   "data_file": "frame0.jpg"}
  {"topic": "/cam/camera_info", "kind": "camera_info", "stamp": [...], "width": W, "height": H,
   "K": [9 values], "D": [5 values], "distortion_model": "plumb_bob"}
Paths in data_file are relative to the manifest.
"""
import json
import os
import sys

import genpy
import rosbag
from sensor_msgs.msg import CameraInfo, CompressedImage, Image


def header(msg, item):
    msg.header.stamp = genpy.Time(item["stamp"][0], item["stamp"][1])
    msg.header.frame_id = item.get("frame_id", "camera")


def read(base, item):
    with open(os.path.join(base, item["data_file"]), "rb") as f:
        return f.read()


def make(base, item):
    kind = item["kind"]
    if kind == "image":
        msg = Image()
        header(msg, item)
        msg.height, msg.width, msg.step = item["height"], item["width"], item["step"]
        msg.encoding = item["encoding"]
        msg.is_bigendian = 0
        msg.data = read(base, item)
        return msg
    if kind == "compressed":
        msg = CompressedImage()
        header(msg, item)
        msg.format = item["format"]
        msg.data = read(base, item)
        return msg
    if kind == "camera_info":
        msg = CameraInfo()
        header(msg, item)
        msg.height, msg.width = item["height"], item["width"]
        msg.distortion_model = item.get("distortion_model", "plumb_bob")
        msg.D = item.get("D", [0.0] * 5)
        msg.K = item["K"]
        msg.R = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
        k = item["K"]
        msg.P = [k[0], 0.0, k[2], 0.0, 0.0, k[4], k[5], 0.0, 0.0, 0.0, 1.0, 0.0]
        return msg
    raise ValueError("unknown kind " + kind)


def main():
    manifest_path, out_path = sys.argv[1], sys.argv[2]
    with open(manifest_path) as f:
        items = json.load(f)
    base = os.path.dirname(os.path.abspath(manifest_path))
    with rosbag.Bag(out_path, "w") as bag:
        for item in items:
            t = genpy.Time(item["stamp"][0], item["stamp"][1])
            bag.write(item["topic"], make(base, item), t)
    print("wrote %d messages to %s" % (len(items), out_path))


if __name__ == "__main__":
    main()
