#!/usr/bin/python3
"""A third-party master: pymodbus (Debian's python3-pymodbus) drives the
simulated controller from docs/modbus-register-map.md alone.

It starts `bezcam simulate --listen 127.0.0.1:0`, reads the port from the
readiness line, reads the whole status block (every register at the address
the document's table gives it), sends a small program with the documented
protocol (OPEN, chunks with sequence numbers and CRC-32, COMMIT), waits for
DONE, checks what the controller reports against the program, checks that
the trace equals the one `bezcam simulate --program` writes for the same
file, and stops the server by its PID.

Usage: pymodbus_check.py BEZCAM_EXE SOURCE_DIR   (exit 0: passed)
Run by ctest as Interop.Pymodbus; needs BEZCAM_MACHINES like every test.
"""
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
import zlib

from pymodbus.client import ModbusTcpClient
from pymodbus.pdu import ExceptionResponse

BEZCAM, SOURCE = sys.argv[1], sys.argv[2]
UNIT = 1
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL: " + what, file=sys.stderr)


def status_table():
    """name -> (address, type) from the document's section 3.1 table."""
    doc = open(os.path.join(SOURCE, "docs/modbus-register-map.md"), encoding="utf-8").read()
    section = doc.split("### 3.1", 1)[1].split("###", 1)[0]
    table = {}
    for m in re.finditer(r"^\| (\d+)(?:-(\d+))? \| (\w+) \| (u16|u32|i32) \|", section, re.M):
        table[m.group(3)] = (int(m.group(1)), m.group(4))
    return table


def value(regs, addr, typ):
    if typ == "u16":
        return regs[addr]
    v = (regs[addr] << 16) | regs[addr + 1]  # 32-bit values: high word first
    if typ == "i32" and v >= 1 << 31:
        v -= 1 << 32
    return v


def words(n):
    return [(n >> 16) & 0xFFFF, n & 0xFFFF]


def pack(data):
    """Text two bytes per register, the first in the high half."""
    if len(data) % 2:
        data += b"\0"
    return [(data[i] << 8) | data[i + 1] for i in range(0, len(data), 2)]


def text(regs):
    return b"".join(bytes([r >> 8, r & 0xFF]) for r in regs).rstrip(b"\0").decode()


def read_status(client, fc=3):
    rr = (client.read_holding_registers if fc == 3 else client.read_input_registers)(0, 48, slave=UNIT)
    assert not rr.isError(), rr
    return rr.registers


PROGRAM = (
    "%\nG21 G90 G17\nT1 M06\nS10000 M03\nG00 Z5.\nX0. Y0.\nG01 Z-1. F300.\n"
    + "".join("X%d.%03d Y%d.%03d F1000.\n" % (i % 37, (i * 37) % 1000, (i * 7) % 23, (i * 11) % 1000) for i in range(1, 60))
    + "G01 X0. Y0.\nG02 X10. Y0. I5. J0.\nG00 Z5.\nX12.5 Y-3.25\nM05\nM30\n%\n"
).encode()


def main():
    tmp = tempfile.mkdtemp(prefix="bezcam-pymodbus-")
    prog_file = os.path.join(tmp, "small.nc")
    with open(prog_file, "wb") as f:
        f.write(PROGRAM)
    trace_file = os.path.join(tmp, "streamed.trace")
    server = subprocess.Popen(
        [BEZCAM, "simulate", "--listen", "127.0.0.1:0", "--time-scale", "max", "--machine", "generic", "--buffer", "512",
         "--trace", trace_file, "-q"],
        stdout=subprocess.PIPE, text=True)
    try:
        ready = server.stdout.readline()  # the readiness line, never a sleep
        m = re.search(r"listening on 127\.0\.0\.1:(\d+)", ready)
        assert m, "no readiness line: %r" % ready
        port = int(m.group(1))
        client = ModbusTcpClient("127.0.0.1", port=port, timeout=5)
        assert client.connect(), "cannot connect to port %d" % port
        run(client, prog_file, trace_file)
        client.close()
    finally:
        server.send_signal(signal.SIGTERM)  # by PID: this server only
        rc = server.wait(timeout=30)
        check(rc == 0, "the simulator exits 0 on SIGTERM (got %s)" % rc)
    if failures:
        print("%d check(s) failed" % len(failures), file=sys.stderr)
        return 1
    print("pymodbus %s drove the transfer of %d bytes; every check passed" % (__import__("pymodbus").__version__, len(PROGRAM)))
    return 0


def run(client, prog_file, trace_file):
    reg = status_table()
    for name in ("magic", "version", "buffer_capacity", "max_chunk", "session", "state", "ack_seq", "ack_bytes",
                 "buffer_free", "lines_executed", "blocks_executed", "program_crc", "pos_x", "pos_y", "pos_z",
                 "flags", "tool", "duplicates", "rejects", "total_bytes"):
        check(name in reg, "register %s is in the document's status table" % name)

    def get(regs, name):
        a, t = reg[name]
        return value(regs, a, t)

    # 1. The status block, through holding (FC 03) and input (FC 04) reads.
    st = read_status(client)
    check(st == read_status(client, 4), "FC 03 and FC 04 read the same status block")
    check(get(st, "magic") == 0x425A, "magic 0x425A")
    check(get(st, "version") == 1, "protocol version 1")
    check(get(st, "buffer_capacity") == 512, "buffer_capacity is --buffer 512")
    max_chunk = get(st, "max_chunk")
    check(max_chunk == 228, "max_chunk 228")
    check(get(st, "state") == 0, "state IDLE at start")
    rr = client.read_holding_registers(128, 16, slave=UNIT)
    check(not rr.isError() and text(rr.registers) == "generic", "machine_name reads 'generic'")

    # ---- starvation figures (docs/modbus-register-map.md) --------------------
    # The motion planner's starvation registers: read when the document lists
    # them, by the names it gives them; a controller that documents them
    # must report them as whole numbers, zero before any program ran.
    # (starved_ms and a count of stalls: any status register whose name
    # starts with "starv" or "stall".)
    starvation = sorted(n for n in reg if n.startswith(("starv", "stall")))
    for name in starvation:
        check(get(st, name) == 0, "%s is 0 before any program" % name)
    # ---------------------------------------------------------------------------

    # A write to the read-only status: a standard exception 02.
    wr = client.write_register(6, 0, slave=UNIT)
    check(isinstance(wr, ExceptionResponse) and wr.exception_code == 2,
          "a write to the status answers exception 02 (got %s)" % wr)

    # 2. OPEN (FC 16 at 0x0100): code 1, token, total bytes.
    token = 0x5059_4D42  # "PYMB"
    total = len(PROGRAM)
    wr = client.write_registers(0x0100, [1] + words(token) + words(total), slave=UNIT)
    check(not wr.isError(), "OPEN accepted")
    st = read_status(client)
    session = get(st, "session")
    check(get(st, "state") == 1 and session != 0, "RECEIVING with a session after OPEN")
    check(get(st, "total_bytes") == total, "total_bytes is OPEN's")

    # 3. Chunks: seq = ack_seq + 1, at most min(max_chunk, buffer_free) bytes,
    # FC 23 (write the chunk, read registers 4-15 back) and FC 16 in turn.
    sent, seq, deadline = 0, 0, time.time() + 60
    while sent < total:
        assert time.time() < deadline, "the transfer stalled at %d bytes" % sent
        free = get(read_status(client), "buffer_free")
        n = min(max_chunk, free, total - sent)
        if n <= 0:
            time.sleep(0.01)  # the controller is executing: poll again
            continue
        payload = PROGRAM[sent:sent + n]
        seq += 1
        chunk = words(session) + words(seq) + [n] + words(zlib.crc32(payload)) + pack(payload)
        if seq % 2:
            rr = client.readwrite_registers(read_address=4, read_count=12, write_address=0x0200,
                                            write_registers=chunk, slave=UNIT)
            check(not rr.isError(), "chunk %d (FC 23) accepted" % seq)
            back = [0] * 4 + rr.registers
        else:
            wr = client.write_registers(0x0200, chunk, slave=UNIT)
            check(not wr.isError(), "chunk %d (FC 16) accepted" % seq)
            back = read_status(client)
        sent += n
        check(get(back, "ack_seq") == seq and get(back, "ack_bytes") == sent,
              "chunk %d acknowledged: ack_seq %d ack_bytes %d" % (seq, get(back, "ack_seq"), get(back, "ack_bytes")))
    # A retransmission of the last chunk: acknowledged again, not applied.
    wr = client.write_registers(0x0200, chunk, slave=UNIT)
    check(not wr.isError(), "a retransmitted chunk is acknowledged")
    st = read_status(client)
    check(get(st, "ack_bytes") == total and get(st, "duplicates") == 1, "the retransmission is counted, not applied")

    # 4. COMMIT: code 3, token, session, total bytes, CRC-32 of the program.
    crc = zlib.crc32(PROGRAM)
    wr = client.write_registers(0x0100, [3] + words(token) + words(session) + words(total) + words(crc), slave=UNIT)
    check(not wr.isError(), "COMMIT accepted")

    # 5. Until DONE (or ALARM).
    deadline = time.time() + 60
    while True:
        st = read_status(client, 4)
        if get(st, "state") in (3, 4) or time.time() > deadline:
            break
        time.sleep(0.02)
    if get(st, "state") == 4:
        rr = client.read_holding_registers(64, 64, slave=UNIT)
        check(False, "ALARM %d at line %d: %s" % (get(st, "alarm"), get(st, "alarm_line"), text(rr.registers)))
        return
    check(get(st, "state") == 3, "DONE")
    lines = PROGRAM.decode().splitlines()
    check(get(st, "lines_executed") == len(lines), "lines_executed %d == %d lines" % (get(st, "lines_executed"), len(lines)))
    moves = sum(1 for l in lines if re.match(r"^(G0[0-3] |X|G00 Z|G01 Z)", l))
    check(get(st, "blocks_executed") == moves, "blocks_executed %d == %d moves" % (get(st, "blocks_executed"), moves))
    check(get(st, "program_crc") == crc, "program_crc equals the CRC-32 sent")
    check((get(st, "pos_x"), get(st, "pos_y"), get(st, "pos_z")) == (12500, -3250, 5000),
          "the position is the program's last point, in micrometres (i32, negative Y)")
    check(get(st, "flags") & 8 and not get(st, "flags") & 1, "flags: program end, spindle off")
    check(get(st, "tool") == 1, "tool 1")
    for name in starvation:  # starvation figures after a program (see above)
        check(get(st, name) >= 0, "%s reads as a count after the program" % name)

    # 6. The program as executed equals the file: the same trace as a direct run.
    direct = trace_file + ".direct"
    r = subprocess.run([BEZCAM, "simulate", "--program", prog_file, "--machine", "generic", "--trace", direct, "-q"])
    check(r.returncode == 0, "simulate --program runs the file")
    streamed = open(trace_file).read()
    check(streamed == open(direct).read() and "done lines %d" % len(lines) in streamed,
          "the streamed trace equals the direct run's")


if __name__ == "__main__":
    sys.exit(main())
