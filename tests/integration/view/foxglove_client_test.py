#!/usr/bin/env python3
"""ifar view as a Foxglove WebSocket server, with real processes: `ifar view` on a private LCM URL and a free
loopback port, goals published with `ifar goal` on that URL, and a WebSocket client (python3-websockets)
that connects to /foxglove with the subprotocol foxglove.websocket.v1 as Foxglove and Lichtblick do. It checks
serverInfo comes first, GOAL is advertised with encoding json, schemaName goal_t and a JSON Schema (strict
JSON) naming goal_t's fields; after subscribing, the goal published before arrives at once and one published
later as it comes, each a Message Data frame (opcode 1, the subscription id, a receive time near now) whose
payload is the goal's JSON with the values sent; after unsubscribing nothing more comes; a request for an
unknown channel is answered with an error status; a client offering ours among others gets ours; and a
client without the subprotocol is refused.
    foxglove_client_test.py            (PATH with build/bin first; IFAR_SOURCE_DIR set by ctest)"""
import asyncio
import json
import os
import re
import signal
import struct
import subprocess
import sys
import tempfile
import time

SOURCE = os.environ.get("IFAR_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..", ".."))
LCM_URL = "udpm://239.255.76.67:7891?ttl=0"
SUBPROTOCOL = "foxglove.websocket.v1"
STARTED = time.monotonic()

try:
    import websockets
except ImportError:
    # Debian's python3-websockets is for Debian's python3; a python3 of another installation (pyenv) first on
    # PATH does not see it.
    if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    print("python3-websockets is not installed (scripts/setup installs it)", flush=True)
    sys.exit(1)


def log(text):
    print(f"[{time.monotonic() - STARTED:5.1f} s] {text}", flush=True)


class Failure(Exception):
    pass


def check(condition, text):
    if not condition:
        raise Failure(text)


def publish_goal(x, y, goal_id):
    subprocess.run(["ifar", "goal", f"{x},{y}", "--id", str(goal_id), "--repeats", "1", "--lcm-url", LCM_URL],
                   check=True, timeout=20, stdout=subprocess.DEVNULL)


async def next_text(socket, timeout=10.0):
    """The next text frame as JSON, skipping nothing: binary here is a failure."""
    frame = await asyncio.wait_for(socket.recv(), timeout)
    check(isinstance(frame, str), f"a text frame was due, got {len(frame)} binary bytes")
    return json.loads(frame)


async def advertised_channel(socket, topic, timeout=15.0):
    """Waits, publishing goals the while, until `topic` is advertised; returns its channel."""
    deadline = time.monotonic() + timeout
    goal_id = 900
    while time.monotonic() < deadline:
        publish_goal(1.0, 2.0, goal_id)
        goal_id += 1
        try:
            message = await next_text(socket, timeout=1.0)
        except asyncio.TimeoutError:
            continue
        check(message.get("op") == "advertise", f"advertise was due, got {message}")
        for channel in message["channels"]:
            if channel["topic"] == topic:
                return channel
    raise Failure(f"{topic} was never advertised")


async def message_data(socket, timeout=10.0):
    frame = await asyncio.wait_for(socket.recv(), timeout)
    check(isinstance(frame, bytes), f"a binary Message Data frame was due, got text {frame}")
    check(len(frame) > 13, f"Message Data is 13 bytes and a payload; got {len(frame)}")
    opcode, subscription, nanoseconds = struct.unpack_from("<BIQ", frame, 0)
    return opcode, subscription, nanoseconds, json.loads(frame[13:].decode())


async def session(url):
    async with websockets.connect(url, subprotocols=[SUBPROTOCOL], max_size=None) as socket:
        check(socket.subprotocol == SUBPROTOCOL, f"the server chose subprotocol {socket.subprotocol!r}")
        info = await next_text(socket)
        check(info.get("op") == "serverInfo", f"serverInfo must come first, got {info}")
        check(info.get("name") == "ifar view", f"serverInfo names {info.get('name')!r}")
        check(info.get("metadata", {}).get("lcm_url") == LCM_URL, f"metadata: {info.get('metadata')}")
        first = await next_text(socket)
        check(first.get("op") == "advertise", f"an advertise follows serverInfo, got {first}")
        log(f"serverInfo and advertise of {len(first['channels'])} channels")

        # The first goal makes the channel: it is advertised to the connected client.
        channel = next((c for c in first["channels"] if c["topic"] == "GOAL"), None) or \
            await advertised_channel(socket, "GOAL")
        check(channel["encoding"] == "json", f"encoding {channel['encoding']}")
        check(channel["schemaName"] == "goal_t", f"schemaName {channel['schemaName']}")
        check(channel["schemaEncoding"] == "jsonschema", f"schemaEncoding {channel.get('schemaEncoding')}")
        schema = json.loads(channel["schema"])  # strict JSON
        check(schema["type"] == "object" and set(schema["properties"]) == {"utime", "goal_id", "x", "y", "cancel"},
              f"goal_t's schema: {schema}")
        log(f"GOAL advertised as channel {channel['id']} with a JSON Schema of {len(channel['schema'])} bytes")

        # The newest goal the view holds comes at once on subscribing.
        publish_goal(3.5, -2.25, 4242)
        await asyncio.sleep(0.5)
        subscription = 0x01020304
        await socket.send(json.dumps({"op": "subscribe",
                                      "subscriptions": [{"id": subscription, "channelId": channel["id"]}]}))
        opcode, got_subscription, nanoseconds, goal = await message_data(socket)
        check(opcode == 1, f"opcode {opcode}")
        check(got_subscription == subscription, f"subscription id {got_subscription:#x}")
        check(abs(nanoseconds / 1e9 - time.time()) < 30, f"receive time {nanoseconds} ns is not near now")
        check((goal["goal_id"], goal["x"], goal["y"], goal["cancel"]) == (4242, 3.5, -2.25, False),
              f"the newest goal decoded wrong: {goal}")
        log(f"on subscribing: goal {goal['goal_id']} at ({goal['x']}, {goal['y']})")

        # A live one as it comes.
        publish_goal(-7.125, 11.5, 4243)
        opcode, got_subscription, _, goal = await message_data(socket)
        check((opcode, got_subscription) == (1, subscription), f"opcode {opcode}, subscription {got_subscription}")
        check((goal["goal_id"], goal["x"], goal["y"]) == (4243, -7.125, 11.5), f"the live goal decoded wrong: {goal}")
        log(f"live: goal {goal['goal_id']} at ({goal['x']}, {goal['y']})")

        # A channel nobody advertised: an error status, and the connection stays.
        await socket.send(json.dumps({"op": "subscribe", "subscriptions": [{"id": 7, "channelId": 99999}]}))
        status = await next_text(socket)
        check(status.get("op") == "status" and status.get("level") == 2, f"an error status was due, got {status}")
        log(f"unknown channel answered: {status['message']}")

        # After unsubscribing, nothing more.
        await socket.send(json.dumps({"op": "unsubscribe", "subscriptionIds": [subscription]}))
        await asyncio.sleep(0.3)
        publish_goal(0.5, 0.5, 4244)
        try:
            frame = await asyncio.wait_for(socket.recv(), 2.0)
            raise Failure(f"after unsubscribing, a frame came: {frame!r}")
        except asyncio.TimeoutError:
            log("after unsubscribing: nothing")


async def chosen_among_others(url):
    """A client offering a newer subprotocol first and ours second gets ours."""
    async with websockets.connect(url, subprotocols=["foxglove.example.v9", SUBPROTOCOL]) as socket:
        check(socket.subprotocol == SUBPROTOCOL, f"the server chose {socket.subprotocol!r} of two")
        info = await next_text(socket)
        check(info.get("op") == "serverInfo", f"serverInfo must come first, got {info}")
        log(f"offered two subprotocols: {socket.subprotocol} chosen")


async def refused_without_subprotocol(url, offered):
    try:
        async with websockets.connect(url, subprotocols=offered) as socket:
            await asyncio.wait_for(socket.recv(), 3.0)
    except (websockets.exceptions.InvalidHandshake, websockets.exceptions.ConnectionClosed,
            ConnectionError, asyncio.TimeoutError) as error:
        log(f"offering {offered}: refused ({type(error).__name__})")
        return
    raise Failure(f"a client offering {offered} was served")


def main():
    work = tempfile.mkdtemp(prefix="ifar_view_foxglove_")
    environment = dict(os.environ, LCM_DEFAULT_URL=LCM_URL)
    view = subprocess.Popen(["ifar", "view", "--port", "0", "--address", "127.0.0.1", "--lcm-url", LCM_URL],
                            cwd=SOURCE, env=environment, stdout=subprocess.PIPE,
                            stderr=open(os.path.join(work, "view.err"), "w"), text=True)
    try:
        url = None
        for _ in range(3):
            line = view.stdout.readline()
            match = re.search(r"Foxglove: (ws://127\.0\.0\.1:\d+/foxglove)", line)
            if match:
                url = match.group(1)
                break
        check(url is not None, "ifar view did not print its Foxglove URL")
        log(f"ifar view: {url}")
        asyncio.run(session(url))
        asyncio.run(chosen_among_others(url))
        asyncio.run(refused_without_subprotocol(url, None))
        asyncio.run(refused_without_subprotocol(url, ["foxglove.example.v9"]))
        check(view.poll() is None, f"ifar view ended (exit {view.returncode})")
    except (Failure, subprocess.SubprocessError, OSError, KeyError, ValueError,
            websockets.exceptions.WebSocketException) as error:
        log(f"FAIL: {type(error).__name__}: {error}")
        with open(os.path.join(work, "view.err")) as errors:
            sys.stdout.write(errors.read()[-3000:])
        return 1
    finally:
        view.send_signal(signal.SIGINT)
        try:
            view.wait(timeout=10)
        except subprocess.TimeoutExpired:
            view.kill()
            view.wait()
    log("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
