#!/usr/bin/python3
"""WebSocket readers for web_console, as N browsers would connect (deploy/load_test.sh
--console-clients N). Each reads every frame the console sends; with --stall-one, client 0 stops
reading after --stall-after seconds, as a browser tab that froze would, and the console has to
drop it without harm.
Prints one JSON summary at the end (or on SIGTERM/SIGINT): frames and bytes per client, and how
each ended.

  console_clients.py --url ws://127.0.0.1:8080/ --clients 10 --duration 60 [--stall-one] [--json F]
Needs Debian's python3-websocket (websocket-client).
"""
import argparse
import json
import signal
import socket
import sys
import threading
import time


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--url", default="ws://127.0.0.1:8080/")
    parser.add_argument("--clients", type=int, default=10)
    parser.add_argument("--duration", type=float, default=60.0, help="seconds")
    parser.add_argument("--stall-one", action="store_true", help="client 0 stops reading at --stall-after")
    parser.add_argument("--stall-after", type=float, default=5.0, help="seconds of reading before the stall")
    parser.add_argument("--json", help="write the summary here too")
    args = parser.parse_args()
    if not 1 <= args.clients <= 256 or not args.duration > 0:
        print("console_clients: --clients in 1..256 and --duration > 0", file=sys.stderr)
        return 64
    try:
        import websocket  # Debian python3-websocket
    except ImportError:
        print("console_clients: python3-websocket missing (deploy/install-deps.sh)", file=sys.stderr)
        return 2

    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    signal.signal(signal.SIGINT, lambda *_: stop.set())
    http_origin = args.url.replace("ws://", "http://", 1).rstrip("/")
    results = [{"client": i, "frames": 0, "bytes": 0, "end": "running"} for i in range(args.clients)]
    started = time.monotonic()

    def reader(i):
        r = results[i]
        stall_at = started + args.stall_after if (args.stall_one and i == 0) else None
        # The staller's small receive buffer: its TCP window closes within a second of it stopping,
        # as a frozen browser's would behind a slow link, instead of the loopback's megabytes
        # taking minutes to fill.
        sockopt = ((socket.SOL_SOCKET, socket.SO_RCVBUF, 4096),) if stall_at is not None else ()
        try:
            ws = websocket.create_connection(args.url, timeout=2.0, origin=http_origin, sockopt=sockopt)
        except Exception as e:  # the console refused or is not there: say so, per client
            r["end"] = f"connect failed: {e}"
            return
        try:
            while not stop.is_set():
                if stall_at is not None and time.monotonic() >= stall_at:
                    r["end"] = "stopped reading (stall)"
                    stop.wait()  # holds the socket open without reading
                    return
                try:
                    frame = ws.recv()
                except websocket.WebSocketTimeoutException:
                    continue
                r["frames"] += 1
                r["bytes"] += len(frame)
            r["end"] = "ran to the end"
        except Exception as e:
            r["end"] = f"closed by the console: {type(e).__name__}"
        finally:
            try:
                ws.close()
            except Exception:
                pass

    threads = [threading.Thread(target=reader, args=(i,), daemon=True) for i in range(args.clients)]
    for t in threads:
        t.start()
    stop.wait(args.duration)
    stop.set()
    for t in threads:
        t.join(timeout=5.0)
    elapsed = time.monotonic() - started
    summary = {"clients": args.clients, "seconds": round(elapsed, 1), "per_client": results,
               "frames_per_s_mean": round(sum(r["frames"] for r in results) / args.clients / elapsed, 1),
               "kbytes_per_s_mean": round(sum(r["bytes"] for r in results) / args.clients / elapsed / 1000, 1)}
    text = json.dumps(summary, indent=1)
    print(text)
    if args.json:
        with open(args.json, "w") as f:
            f.write(text + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
