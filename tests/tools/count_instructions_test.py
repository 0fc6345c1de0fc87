#!/usr/bin/env python3
"""scripts/count_instructions.py's reading of a callgrind file, on hand-written files whose
totals and call counts are known (names compressed as callgrind writes them: "(id) name" the
first time, "(id)" after)."""

import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import count_instructions  # noqa: E402

# A drive: the benchmark body calls Recover 2 times in a sizing run and 12 times in the timed
# run; Recover calls Detect (not a Recover: not counted) and a second Recover overload once per
# frame (a call from inside Recover: not a frame).
DRIVE = """version: 1
creator: callgrind-3.19.0
events: Ir
summary: 1400

fn=(1) corridor::(anonymous namespace)::EndToEndDrive(benchmark::State&, bool, int, int)
cfn=(2) corridor::DepthRecoverer::Recover(cv::Mat const&, corridor::Camera const&, corridor::RecoverDepthResult*) const
calls=12 0
0 1200
cfn=(2)
calls=2 0
0 200

fn=(2)
0 10
cfn=(3) corridor::DepthRecoverer::Detect(cv::Mat const&) const
calls=14 0
0 600
cfn=(4) corridor::DepthRecoverer::Recover(cv::Mat const&, corridor::Camera const&, corridor::RecoverDepthResult*, corridor::CorridorGeometry const*, corridor::JunctionTrack*) const
calls=14 0
0 500

totals: 1400
"""


class ReadCallgrindTest(unittest.TestCase):
    def read(self, text, frame=None):
        with tempfile.NamedTemporaryFile("w", suffix=".out", delete=False) as f:
            f.write(text)
            path = f.name
        try:
            if frame is None:
                return count_instructions.recover_calls_and_total(path)
            return count_instructions.recover_calls_and_total(path, frame)
        finally:
            os.remove(path)

    def test_counts_frames_from_outside_recover_only(self):
        self.assertEqual(self.read(DRIVE), (1400, 14))

    def test_no_recover_call_gives_zero_frames(self):
        text = "events: Ir\nsummary: 50\nfn=(1) main\n0 50\ntotals: 50\n"
        self.assertEqual(self.read(text), (50, 0))

    def test_summary_used_when_totals_missing(self):
        text = DRIVE.replace("totals: 1400\n", "")
        self.assertEqual(self.read(text), (1400, 14))

    def test_floor_frames_counted_by_their_own_function(self):
        # The grey floor's body called 5 times; Recover never: its frames are the 5 calls.
        text = ("events: Ir\nsummary: 500\n"
                "fn=(1) corridor::(anonymous namespace)::FloorGrey(benchmark::State&, int, int)\n"
                "cfn=(2) corridor::bench::FloorGreyFrame(cv::Mat const&, int, cv::Mat*, "
                "cv::Mat*, cv::Mat*)\ncalls=5 0\n0 500\nfn=(2)\n0 500\ntotals: 500\n")
        _, floor_grey = count_instructions.FLOOR_FRAMES["floor_grey"]
        _, floor = count_instructions.FLOOR_FRAMES["floor"]
        self.assertEqual(self.read(text, floor_grey), (500, 5))
        self.assertEqual(self.read(text, floor), (500, 0))
        self.assertEqual(self.read(text), (500, 0))


if __name__ == "__main__":
    unittest.main()
