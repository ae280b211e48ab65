#!/usr/bin/env python3
"""ifar-sim smoke test: runs the daemon on a built-in world for a few seconds and checks that VLP-16
packets arrive by UDP at the sensor's rate with the right header bytes, and that POSE, SIM_GROUND_TRUTH
and the CAN bridge channel appear on LCM (recorded with lcm-logger on a private multicast port)."""
import os
import socket
import subprocess
import sys
import tempfile
import time

SOURCE = os.environ.get("IFAR_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
UDP_PORT = 23713  # this test's own lidar port, next to its LCM port
LCM_URL = "udpm://239.255.76.67:7713?ttl=0"


def main():
    with tempfile.TemporaryDirectory() as folder:
        log = os.path.join(folder, "sim.lcmlog")
        env = dict(os.environ, LCM_DEFAULT_URL=LCM_URL)
        receiver = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        receiver.bind(("127.0.0.1", UDP_PORT))
        receiver.settimeout(0.2)
        logger = subprocess.Popen(["lcm-logger", "--lcm-url=" + LCM_URL, "-f", log],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        time.sleep(0.3)
        simulator = subprocess.Popen(["ifar-sim", "--set", "lidar.port=%d" % UDP_PORT, "--builtin", "push_light",
                                      "--log-dir", folder], cwd=SOURCE, env=env)
        packets = []
        first = last = None
        deadline = time.time() + 3.0
        while time.time() < deadline:
            try:
                packets.append(receiver.recv(2048))
                last = time.time()
                first = first or last
            except socket.timeout:
                pass
        simulator.terminate()
        code = simulator.wait(timeout=5)
        logger.terminate()
        logger.wait(timeout=5)
        problems = []
        if code != 0:
            problems.append("ifar-sim exited with %d" % code)
        rate = (len(packets) - 1) / (last - first) if len(packets) > 1 else 0.0
        if not 700 <= rate <= 800:
            problems.append("%d packets, %.0f per second (want about 754)" % (len(packets), rate))
        bad = [p for p in packets if len(p) != 1206 or p[0:2] != b"\xff\xee" or p[1204] != 0x37 or p[1205] != 0x22]
        if bad:
            problems.append("%d packets with a wrong size or header" % len(bad))
        content = open(log, "rb").read() if os.path.exists(log) else b""
        for channel in (b"POSE", b"SIM_GROUND_TRUTH", b"CAN_VEHICLE"):
            if channel not in content:
                problems.append("no %s message on LCM" % channel.decode())
        if problems:
            print("FAIL: " + "; ".join(problems))
            return 1
        print("OK: %d packets at %.0f/s; POSE, SIM_GROUND_TRUTH, CAN_VEHICLE seen" % (len(packets), rate))
        return 0


if __name__ == "__main__":
    sys.exit(main())
