#!/usr/bin/env python3
"""Hostile-environment tests of the tools' file discipline (ctest label "hostile").

Aliasing outputs, symlinks and FIFOs where files are expected, a full disk, signals at the worst
moment, header bombs, absurd flags, concurrent writers of one output, and `fpstereo synth`
interrupted while Yosys runs (a stand-in yosys that waits). Every refusal must be one line with
exit 2, and no previous output may be changed, no temporary left behind.

usage: hostile.py FPSTEREO FPSTEREO_RTL EXAMPLES_DIR WORK_DIR
"""
import os
import shutil
import signal
import struct
import subprocess
import sys
import time
import zlib

FPSTEREO, FPSTEREO_RTL, EXAMPLES, WORK = sys.argv[1:5]
LEFT = os.path.join(EXAMPLES, "cones", "left.png")
RIGHT = os.path.join(EXAMPLES, "cones", "right.png")
SMALL = ["--width", "450", "--height", "375", "--dmax", "64", "--uf", "16"]
failures = []


def check(ok, what):
    print(("ok:   " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)


def run(args, timeout=60, env=None, **kw):
    return subprocess.run(args, capture_output=True, text=True, errors="replace", timeout=timeout, env=env, **kw)


def expect_refusal(args, expected, what, timeout=30):
    try:
        r = run(args, timeout=timeout)
    except subprocess.TimeoutExpired:
        check(False, f"{what}: hung (no answer in {timeout} s)")
        return
    err = r.stderr.strip()
    check(r.returncode == 2 and "\n" not in err and expected in err,
          f"{what}: exit 2 and one line with {expected!r} (got {r.returncode}: {err[:300]!r})")


def fresh(name):
    path = os.path.join(WORK, name)
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path


def leftovers(directory):
    return [n for n in os.listdir(directory) if ".tmp." in n]


def read(path):
    with open(path, "rb") as f:
        return f.read()


def write(path, data):
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def inputs(d):
    left, right = os.path.join(d, "L.png"), os.path.join(d, "R.png")
    shutil.copy(LEFT, left)
    shutil.copy(RIGHT, right)
    return left, right


def aliasing():
    d = fresh("alias")
    left, right = inputs(d)
    original = read(left)
    expect_refusal([FPSTEREO, "run", left, right, *SMALL, "-o", left], "is the same file as left image",
                   "run -o LEFT")
    expect_refusal([FPSTEREO, "run", left, right, *SMALL, "--gray-pgm", left, right], "is the same file as",
                   "run --gray-pgm LEFT RIGHT")
    os.symlink(left, os.path.join(d, "link.png"))
    expect_refusal([FPSTEREO, "run", left, right, *SMALL, "-o", os.path.join(d, "link.png")],
                   "is the same file as left image", "run -o a symlink to LEFT")
    expect_refusal([FPSTEREO, "run", left, right, *SMALL, "-o", os.path.join(d, "x"), "--pfm",
                    os.path.join(d, ".", "x")], "is the same file as --output", "run -o x --pfm ./x")
    check(read(left) == original and read(right) == read(RIGHT), "aliased inputs unchanged")
    r = run([FPSTEREO, "run", left, right, *SMALL, "-o", "/dev/null", "--pfm", "/dev/null"])
    check(r.returncode == 0, f"two outputs to /dev/null, a device that replaces nothing ({r.stderr.strip()!r})")
    write(os.path.join(d, "in.csv"), "previous")
    expect_refusal([FPSTEREO, "dse", "merge", os.path.join(d, "in.csv"), "-o", os.path.join(d, "in.csv"),
                    "--html", ""], "is the same file as input CSV", "dse merge -o INPUT")
    expect_refusal([FPSTEREO, "eval", os.path.join(EXAMPLES, "cones"), "--json", os.path.join(d, "r"), "--csv",
                    os.path.join(d, "r")], "is the same file as --json", "eval --json F --csv F")
    expect_refusal([FPSTEREO, "eval", os.path.join(EXAMPLES, "cones"), "--json", os.path.join(EXAMPLES, "cones", "left.png")],
                   "is the same file as --json", "eval --json onto a pair's image")
    write(os.path.join(d, "cfg.json"), '{"dmax": 64, "uf": 16}')
    expect_refusal([FPSTEREO_RTL, "--config", os.path.join(d, "cfg.json"), "-o", d], "lies inside -o directory",
                   "fpstereo-rtl -o DIR holding its --config")


def symlinks():
    d = fresh("symlinks")
    left, right = inputs(d)
    victim = os.path.join(WORK, "victim.txt")
    write(victim, "victim")
    out = os.path.join(d, "rtl")
    r = run([FPSTEREO_RTL, "--preset", "C2", "-o", out])
    check(r.returncode == 0, "fpstereo-rtl -o DIR")
    os.remove(os.path.join(out, "config.json"))
    os.symlink(victim, os.path.join(out, "config.json"))
    os.symlink(victim, os.path.join(out, "Makefile"))
    r = run([FPSTEREO_RTL, "--preset", "C2", "-o", out])
    check(r.returncode == 0 and read(victim) == b"victim" and not os.path.islink(os.path.join(out, "config.json")),
          "fpstereo-rtl -o DIR replaces a symlink in DIR, never writes through it")
    link = os.path.join(d, "d.png")
    os.symlink(victim, link)
    r = run([FPSTEREO, "run", left, right, *SMALL, "-o", link])
    check(r.returncode == 0 and read(victim) == b"victim" and not os.path.islink(link),
          "run -o SYMLINK replaces the link, not the file it points to")
    mine = fresh("user_dir")
    write(os.path.join(mine, "notes.txt"), "mine")
    expect_refusal([FPSTEREO_RTL, "--preset", "C2", "-o", mine], "which this run does not write",
                   "fpstereo-rtl -o a directory holding other files")
    check(read(os.path.join(mine, "notes.txt")) == b"mine", "a user's directory stays as it was")


def fifos():
    d = fresh("fifos")
    os.makedirs(os.path.join(d, "set"))
    os.mkfifo(os.path.join(d, "set", "pairs.csv"))
    expect_refusal([FPSTEREO, "dse", os.path.join(d, "set"), "-o", os.path.join(d, "o.csv"), "--html", "",
                    "--cache", os.path.join(d, "cache")], "not a regular file", "dse with a FIFO pairs.csv", 20)
    expect_refusal([FPSTEREO, "eval", os.path.join(d, "set")], "not a regular file", "eval with a FIFO pairs.csv",
                   20)
    # A FIFO where a dse cache record should be: refused at once.
    cache = os.path.join(d, "cache")
    sweep = [FPSTEREO, "dse", os.path.join(EXAMPLES, "cones"), "--cost", "census", "--window", "5", "--dmax", "64",
             "--uf", "16", "--refine", "none", "--median", "off", "--resolution", "450x375", "-o",
             os.path.join(d, "o.csv"), "--html", "", "--cache", cache]
    r = run(sweep, timeout=120)
    check(r.returncode == 0, f"a one-configuration sweep ({r.stderr.strip()[-200:]!r})")
    for name in os.listdir(cache):
        os.remove(os.path.join(cache, name))
        os.mkfifo(os.path.join(cache, name))
    expect_refusal(sweep, "not a regular file", "dse with a FIFO cache record", 20)


def full_disk():
    d = fresh("full")
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=96k", "tmpfs", d], capture_output=True).returncode:
        print("skip: full disk (cannot mount a tmpfs here)")
        return
    try:
        out = os.path.join(d, "rtl")
        os.makedirs(out)
        write(os.path.join(out, "config.json"), "previous")
        write(os.path.join(out, ".fpstereo-output"), "")
        expect_refusal([FPSTEREO_RTL, "--preset", "C2", "-o", out], "No space left on device",
                       "fpstereo-rtl -o DIR on a full disk")
        check(read(os.path.join(out, "config.json")) == b"previous" and sorted(os.listdir(d)) == ["rtl"],
              "full disk: the previous directory untouched, no temporary left")
        left, right = inputs(fresh("full_inputs"))
        write(os.path.join(d, "d.png"), "previous")
        expect_refusal([FPSTEREO, "run", left, right, *SMALL, "-o", os.path.join(d, "d.png"), "--gray-pgm",
                        os.path.join(d, "l.pgm"), os.path.join(d, "r.pgm")], "No space left on device",
                       "run with outputs on a full disk")
        check(read(os.path.join(d, "d.png")) == b"previous" and leftovers(d) == [] and not os.path.exists(
            os.path.join(d, "l.pgm")), "full disk: previous output kept, nothing else written")
    finally:
        subprocess.run(["umount", d])


def signals():
    d = fresh("signals")
    left, right = inputs(d)
    for name in ("d.png", "d.pfm"):
        write(os.path.join(d, name), "previous")
    env = dict(os.environ, FPSTEREO_TEST_SIGNAL_AT_COMMIT=str(int(signal.SIGTERM)))
    r = run([FPSTEREO, "run", left, right, *SMALL, "-o", os.path.join(d, "d.png"), "--pfm", os.path.join(d, "d.pfm")],
            env=env)
    check(r.returncode == -signal.SIGTERM, f"run ends by SIGTERM at commit (got {r.returncode})")
    check(read(os.path.join(d, "d.png")) == b"previous" and read(os.path.join(d, "d.pfm")) == b"previous"
          and leftovers(d) == [], "SIGTERM before commit: both outputs as they were, no temporary")
    out = os.path.join(d, "rtl")
    run([FPSTEREO_RTL, "--preset", "C2", "-o", out])
    before = sorted(os.listdir(out))
    env["FPSTEREO_TEST_SIGNAL_AT_COMMIT"] = str(int(signal.SIGINT))
    r = run([FPSTEREO_RTL, "--preset", "C4", "-o", out], env=env)
    check(r.returncode == -signal.SIGINT and sorted(os.listdir(out)) == before and leftovers(d) == [],
          "fpstereo-rtl: SIGINT before the swap leaves the previous directory and no staged one")


def synth_interrupted():
    """A stand-in yosys that waits: SIGTERM to fpstereo synth, or to a dse synthesising its front,
    must end it, keep --netlist, remove the work."""
    d = fresh("synth")
    bin_dir = os.path.join(d, "bin")
    os.makedirs(bin_dir)
    pid_file = os.path.join(d, "yosys.pid")
    write(os.path.join(bin_dir, "yosys"), f"#!/bin/sh\necho $$ > '{pid_file}'\nexec sleep 300\n")
    os.chmod(os.path.join(bin_dir, "yosys"), 0o755)
    netlist = os.path.join(d, "previous.json")
    write(netlist, "previous")
    cache = os.path.join(d, "cache")
    # a fresh default cache for dse's synth children, so that they run the stand-in
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ["PATH"], XDG_CACHE_HOME=cache)
    dse_out = os.path.join(d, "o.csv")
    write(dse_out, "previous")
    runs = {"synth": [FPSTEREO, "synth", "--preset", "C2", "--cache", os.path.join(cache, "fpstereo", "synth"),
                      "--netlist", netlist],
            "dse --yosys-front": [FPSTEREO, "dse", os.path.join(EXAMPLES, "cones"), "--cost", "census", "--window", "5",
                                  "--dmax", "64", "--uf", "16", "--refine", "none", "--median", "off", "--resolution",
                                  "450x375", "-o", dse_out, "--html", "", "--yosys-front", "--yosys-limit", "1"]}
    for what, command in runs.items():
        if os.path.exists(pid_file):
            os.remove(pid_file)
        before_tmp = set(os.listdir("/tmp"))
        p = subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        deadline = time.time() + 120
        while not os.path.exists(pid_file) and time.time() < deadline and p.poll() is None:
            time.sleep(0.05)
        if not os.path.exists(pid_file):
            p.kill()
            check(False, f"{what}: the stand-in yosys never started: " + p.stderr.read().decode()[-300:])
            continue
        time.sleep(0.2)
        yosys = int(read(pid_file).strip() or 0)
        p.send_signal(signal.SIGTERM)
        try:
            p.wait(timeout=20)
        except subprocess.TimeoutExpired:
            p.kill()
        check(p.returncode == -signal.SIGTERM, f"{what} ends by SIGTERM (got {p.returncode})")
        time.sleep(0.2)
        alive = os.path.exists(f"/proc/{yosys}") and "Z" not in read(f"/proc/{yosys}/stat").split(b")")[-1][:3].decode()
        check(not alive, f"{what}: Yosys ends with fpstereo")
        work = os.path.join(cache, "fpstereo", "synth", "work")
        check(not os.path.isdir(work) or os.listdir(work) == [], f"{what}: the work folder is removed")
        new_tmp = [n for n in set(os.listdir("/tmp")) - before_tmp
                   if n.startswith("synth-yosys.") or n.startswith("fpstereo-child.")]
        check(new_tmp == [], f"{what}: the temporaries are removed ({new_tmp})")
    check(read(netlist) == b"previous", "synth: the previous --netlist file is kept")
    check(read(dse_out) == b"previous", "dse: the previous -o file is kept")


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def header_bomb():
    d = fresh("bomb")
    side = 32000
    ihdr = struct.pack(">IIBBBBB", side, side, 8, 0, 0, 0, 0)
    deflate = zlib.compressobj(9)  # a whole, valid image of zeros: about 1 MB for 1 GB of pixels
    body = b"".join(deflate.compress(b"\0" * (side + 1)) for _ in range(side)) + deflate.flush()
    write(os.path.join(d, "bomb.png"), b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) + png_chunk(b"IDAT", body)
          + png_chunk(b"IEND", b""))
    write(os.path.join(d, "bomb.pgm"), f"P5\n{side} {side}\n255\n".encode() + b"\0" * 1000)
    limit = "ulimit -v 1000000; exec \"$0\" \"$@\""  # 1 GB: a decoded bomb would not fit
    # a side of 20 digits: the height after it read as the height, not as the width's last digits
    write(os.path.join(d, "long.pgm"), b"P5\n99999999999999999999 2\n255\n" + b"\0" * 100)
    expect_refusal([FPSTEREO, "run", os.path.join(d, "long.pgm"), RIGHT], "(13 digits or more)x2 pixels",
                   "a PGM whose width has 20 digits")
    for bomb in ("bomb.png", "bomb.pgm"):
        start = time.time()
        expect_refusal(["sh", "-c", limit, FPSTEREO, "run", os.path.join(d, bomb), RIGHT], "header states 32000x32000",
                       f"a {bomb} claiming {side}x{side}")
        check(time.time() - start < 5, f"{bomb} refused from its header, quickly")


def memory_limits():
    """Under every address-space limit from the one the program starts in up to the one it needs,
    a run either succeeds or refuses with one line naming no C++ exception (no crash, no
    "std::bad_alloc"), and the previous output stays as it was."""
    d = fresh("memory")
    left, right = inputs(d)
    out = os.path.join(d, "d.png")
    write(out, b"previous")
    limited = lambda kb, *args: run(["sh", "-c", f"ulimit -v {kb}; exec \"$0\" \"$@\"", FPSTEREO, *args])
    start = next((kb for kb in range(50_000, 2_000_000, 2_000) if limited(kb, "config").returncode == 0), None)
    if start is None:
        check(False, "fpstereo config starts under no address-space limit up to 2 GB")
        return
    results = []
    for kb in range(start, start + 400_000, 1_000):
        r = limited(kb, "run", left, right, *SMALL, "-o", out)
        results.append(r)
        if r.returncode == 0:
            break
        err = r.stderr.strip()
        check(r.returncode == 2 and "\n" not in err and "std::" not in err and "bad_alloc" not in err and
              read(out) == b"previous", f"under {kb} kB: exit 2, one line, output untouched (got {r.returncode}: {err!r})")
    check(results and results[-1].returncode == 0, f"a run succeeds under some limit from {start} kB on")


def flags():
    huge_part = "a-" + "b" * 30000
    expect_refusal([FPSTEREO_RTL, "--emit", "hls", "--part", huge_part, "-o", os.path.join(WORK, "hls_part")],
                   "expected a Xilinx part name", "a 30,000-character --part")
    cones = os.path.join(EXAMPLES, "cones")
    out = ["-o", os.path.join(WORK, "f.csv"), "--html", "", "--cache", os.path.join(WORK, "f_cache")]
    expect_refusal([FPSTEREO, "dse", cones, "--jobs", "100000", *out], "--jobs 100000", "dse --jobs 100000")
    expect_refusal([FPSTEREO, "dse", cones, "-o", ""], "empty file name", "dse -o ''", 10)
    # An empty output name (an unset shell variable) once meant no output at all, with exit 0.
    for flag, name in (("-o", "--output"), ("--colour", "--colour"), ("--pfm", "--pfm"),
                       ("--confidence-output", "--confidence-output")):
        expect_refusal([FPSTEREO, "run", LEFT, RIGHT, *SMALL, flag, ""], f"{name}: an empty file name",
                       f"run {flag} ''", 10)
    expect_refusal([FPSTEREO, "eval", cones, "--csv", ""], "--csv: an empty file name", "eval --csv ''", 10)
    expect_refusal([FPSTEREO, "synth", "--preset", "C2", "--netlist", ""], "--netlist: an empty file name",
                   "synth --netlist ''", 10)
    expect_refusal([FPSTEREO, "dse", cones, "--yosys-limit", "-1", *out], "--yosys-limit -1", "dse --yosys-limit -1")
    expect_refusal([FPSTEREO, "dse", cones, "--min-fps", "nan", *out], "--min-fps 'nan'", "dse --min-fps nan")
    for clock in ("1e308", "inf", "nan", "-1"):
        expect_refusal([FPSTEREO, "dse", cones, "--clock-mhz", clock, *out], "clock-mhz", f"dse --clock-mhz {clock}")
    expect_refusal([FPSTEREO_RTL, "--clock-mhz", "1e-300"], "expected a positive frequency", "--clock-mhz 1e-300")
    expect_refusal([FPSTEREO, "dse", cones, "--cost", "census", "--window", "5", "--dmax", "64", "--uf", "16",
                    "--refine", "none", "--median", "off", "--resolution", "64x16", *out],
                   "smaller than the dataset's largest images", "dse --resolution smaller than the images", 120)


def odd_names():
    """A dataset folder whose name is not UTF-8: --json and --csv are both written."""
    d = fresh("names")
    dataset = os.path.join(d.encode(), b"set\xff").decode(errors="surrogateescape")
    shutil.copytree(os.path.join(EXAMPLES, "cones"), dataset)
    r = run([FPSTEREO, "eval", dataset, "--dmax", "64", "--uf", "16", "--json", os.path.join(d, "r.json"), "--csv",
             os.path.join(d, "r.csv")], timeout=120)
    check(r.returncode == 0 and os.path.getsize(os.path.join(d, "r.json")) > 0 and
          os.path.getsize(os.path.join(d, "r.csv")) > 0, f"eval on a non-UTF-8 folder name ({r.stderr[-200:]!r})")


def concurrent_writers():
    d = fresh("concurrent")
    left, right = inputs(d)
    target = os.path.join(d, "d.png")
    reference = os.path.join(d, "reference.png")
    run([FPSTEREO, "run", left, right, *SMALL, "-o", reference])
    procs = [subprocess.Popen([FPSTEREO, "run", left, right, *SMALL, "-o", target], stdout=subprocess.DEVNULL)
             for _ in range(6)]
    codes = [p.wait(timeout=120) for p in procs]
    check(codes == [0] * 6 and read(target) == read(reference) and leftovers(d) == [],
          "six concurrent writers of one output: one whole file, no temporary")


def device_directory():
    """/dev holds devices and links to open descriptors: a run writes there only into a device or a
    pipe. `-o /dev/stdout` with standard output redirected to a file once replaced the machine's
    /dev/stdout link with a PNG file; a new name in /dev was created as a file."""
    d = fresh("devices")
    left, right = inputs(d)
    stray = "/dev/fpstereo-hostile-test.png"
    expect_refusal([FPSTEREO, "run", left, right, *SMALL, "-o", stray], "in /dev a run writes only into a device",
                   "run -o a new file in /dev")
    check(not os.path.lexists(stray), "nothing created in /dev")
    if os.path.lexists(stray):
        os.remove(stray)
    stray_dir = "/dev/fpstereo-hostile-rtl"
    for name in (stray_dir, stray_dir + "/"):
        expect_refusal([FPSTEREO_RTL, "--preset", "C2", "-o", name], "in /dev a run writes only into a device",
                       f"fpstereo-rtl -o {name}")
    check(not os.path.lexists(stray_dir), "no directory created in /dev")
    if os.path.lexists(stray_dir):
        shutil.rmtree(stray_dir)
    # Caches are directories a run creates: none in /dev either (dse's once was).
    stray_cache = "/dev/fpstereo-hostile-cache"
    out = ["-o", os.path.join(d, "dse.csv"), "--html", os.path.join(d, "dse.html")]
    expect_refusal([FPSTEREO, "dse", os.path.join(EXAMPLES, "cones"), "--cost", "census", "--window", "5", "--dmax",
                    "64", "--uf", "16", "--refine", "none", "--median", "off", "--resolution", "450x375",
                    "--cache", stray_cache + "/sub", *out], "in /dev a run writes only into a device",
                   "dse --cache in /dev", timeout=120)
    # A small design, should the refusal ever be lost: Yosys then ends within the timeout.
    expect_refusal([FPSTEREO, "synth", "--width", "32", "--height", "8", "--dmax", "16", "--uf", "16", "--window", "3",
                    "--median", "0", "--paths", "0", "--cache", stray_cache], "in /dev a run writes only into a device",
                   "synth --cache in /dev", timeout=120)
    check(not os.path.lexists(stray_cache), "no cache directory created in /dev")
    if os.path.lexists(stray_cache):
        shutil.rmtree(stray_cache)
    if os.path.islink("/dev/stdout"):
        with open(os.path.join(d, "stdout.txt"), "w") as redirected:
            r = subprocess.run([FPSTEREO, "run", left, right, *SMALL, "-o", "/dev/stdout"], stdout=redirected,
                               stderr=subprocess.PIPE, text=True, timeout=60)
        intact = os.path.islink("/dev/stdout")
        if not intact:  # put the machine's link back before failing
            os.remove("/dev/stdout")
            os.symlink("/proc/self/fd/1", "/dev/stdout")
        err = r.stderr.strip()
        check(r.returncode == 2 and "\n" not in err and "in /dev a run writes only" in err and intact,
              f"run -o /dev/stdout into a file: refused, /dev/stdout still a link (got {r.returncode}: {err!r})")
        r = subprocess.run([FPSTEREO, "run", left, right, *SMALL, "-o", "/dev/stdout"], capture_output=True,
                           timeout=60)
        check(r.returncode == 0 and r.stdout.startswith(b"\x89PNG") and os.path.islink("/dev/stdout"),
              "run -o /dev/stdout into a pipe: the PNG written through it")
    previous = os.path.join(d, "d.pfm")
    write(previous, "previous")
    expect_refusal([FPSTEREO, "run", left, right, *SMALL, "-o", "/dev/full", "--pfm", previous],
                   "No space left on device", "run -o /dev/full --pfm FILE")
    check(read(previous) == b"previous" and leftovers(d) == [], "/dev/full: the other output kept, no temporary")
    r = subprocess.run([FPSTEREO, "config"], stdout=open("/dev/full", "w"), stderr=subprocess.PIPE, text=True,
                       timeout=30)
    err = r.stderr.strip()
    check(r.returncode == 2 and "\n" not in err and "No space left on device" in err,
          f"fpstereo config > /dev/full: one line, exit 2 (got {r.returncode}: {err!r})")


def links_and_names():
    d = fresh("links")
    left, right = inputs(d)
    original = read(left)
    os.link(left, os.path.join(d, "hard.png"))
    expect_refusal([FPSTEREO, "run", left, right, *SMALL, "-o", os.path.join(d, "hard.png")],
                   "is the same file as left image", "run -o a hard link to LEFT")
    check(read(left) == original, "the hard-linked input unchanged")
    mine = os.path.join(d, "mine")
    os.makedirs(mine)
    write(os.path.join(mine, "notes.txt"), "mine")
    os.symlink(mine, os.path.join(d, "rtl"))
    r = run([FPSTEREO_RTL, "--preset", "C2", "-o", os.path.join(d, "rtl")])
    check(r.returncode == 0 and not os.path.islink(os.path.join(d, "rtl")) and os.listdir(mine) == ["notes.txt"]
          and read(os.path.join(mine, "notes.txt")) == b"mine",
          "fpstereo-rtl -o a symlink to a user's directory: the link replaced, the directory untouched")
    fifo = os.path.join(d, "cfg.json")
    os.mkfifo(fifo)
    expect_refusal([FPSTEREO, "config", "--config", fifo], "not a regular file", "--config a FIFO", 10)
    cache_file = os.path.join(d, "cache")
    write(cache_file, "a file")
    r = run([FPSTEREO, "synth", "--preset", "C2", "--netlist", os.path.join(d, "n.json")],
            env=dict(os.environ, XDG_CACHE_HOME=cache_file), timeout=30)
    err = r.stderr.strip()
    check(r.returncode == 2 and "\n" not in err and "Not a directory" in err and read(cache_file) == b"a file",
          f"synth with XDG_CACHE_HOME a file: one line, exit 2 (got {r.returncode}: {err!r})")
    dataset = os.path.join(d, "set")
    shutil.copytree(os.path.join(EXAMPLES, "cones"), dataset)
    with open(os.path.join(dataset, "pairs.csv"), "r+b") as f:
        f.truncate(100 << 20)  # sparse: 100 MB of NUL bytes after the header
    expect_refusal([FPSTEREO, "eval", dataset], "larger than 64 MiB", "eval with a 100 MB pairs.csv", 10)


def concurrent_directories():
    """Writers of two different designs to one directory: it ends up whole, one of the two."""
    d = fresh("concurrent_rtl")
    refs = {}
    for preset in ("C2", "C3"):
        refs[preset] = os.path.join(d, "ref_" + preset)
        run([FPSTEREO_RTL, "--preset", preset, "-o", refs[preset]])
    target = os.path.join(d, "out")
    procs = [subprocess.Popen([FPSTEREO_RTL, "--preset", ("C2", "C3")[i % 2], "-o", target],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE) for i in range(6)]
    codes = [p.wait(timeout=120) for p in procs]
    contents = lambda path: {n: read(os.path.join(path, n)) for n in os.listdir(path)}
    got = contents(target)
    check(codes == [0] * 6 and got in (contents(refs["C2"]), contents(refs["C3"])) and
          sorted(os.listdir(d)) == ["out", "ref_C2", "ref_C3"],
          f"six writers of two designs to one directory: one whole design, nothing staged left ({codes})")


def signals_in_commit():
    """A signal between two renames of a commit waits for the commit's end: every output new, and no
    swapped-out previous directory left under a temporary's name (once left when its files were
    not the new run's)."""
    d = fresh("swap")
    out = os.path.join(d, "hls")
    run([FPSTEREO_RTL, "--emit", "hls", "--preset", "C2", "-o", out])
    reference = os.path.join(WORK, "swap_reference")
    shutil.rmtree(reference, ignore_errors=True)
    run([FPSTEREO_RTL, "--emit", "hls", "--preset", "C3", "-o", reference])
    env = dict(os.environ, FPSTEREO_TEST_SIGNAL_AT_SWAP=str(int(signal.SIGTERM)))
    r = run([FPSTEREO_RTL, "--emit", "hls", "--preset", "C3", "-o", out], env=env)
    check(r.returncode == -signal.SIGTERM and os.listdir(d) == ["hls"] and
          sorted(os.listdir(out)) == sorted(os.listdir(reference)),
          f"--emit hls: SIGTERM after the swap: the new directory whole, the previous one removed "
          f"(got {r.returncode}, {sorted(os.listdir(d))})")
    left, right = inputs(d)
    for name in ("d.png", "d.pfm"):
        write(os.path.join(d, name), "previous")
    r = run([FPSTEREO, "run", left, right, *SMALL, "-o", os.path.join(d, "d.png"), "--pfm",
             os.path.join(d, "d.pfm")], env=dict(env, FPSTEREO_TEST_SIGNAL_AT_SWAP=str(int(signal.SIGINT))))
    check(r.returncode == -signal.SIGINT and read(os.path.join(d, "d.png")) != b"previous" and
          read(os.path.join(d, "d.pfm")) != b"previous" and leftovers(d) == [],
          f"run: SIGINT after the first rename: both outputs new, no temporary (got {r.returncode})")


def signals_hangup():
    """SIGHUP, the third signal of the discipline, at the commit of eval's two outputs."""
    d = fresh("hangup")
    for name in ("r.json", "r.csv"):
        write(os.path.join(d, name), "previous")
    env = dict(os.environ, FPSTEREO_TEST_SIGNAL_AT_COMMIT=str(int(signal.SIGHUP)))
    r = run([FPSTEREO, "eval", os.path.join(EXAMPLES, "cones"), "--dmax", "64", "--uf", "16", "--json",
             os.path.join(d, "r.json"), "--csv", os.path.join(d, "r.csv")], env=env, timeout=120)
    check(r.returncode == -signal.SIGHUP and read(os.path.join(d, "r.json")) == b"previous" and
          read(os.path.join(d, "r.csv")) == b"previous" and leftovers(d) == [],
          f"eval --json --csv: SIGHUP before commit leaves both outputs and no temporary (got {r.returncode})")


for case in (aliasing, symlinks, fifos, full_disk, signals, synth_interrupted, header_bomb, memory_limits, flags,
             odd_names, concurrent_writers, device_directory, links_and_names, concurrent_directories,
             signals_in_commit, signals_hangup):
    print(f"-- {case.__name__}")
    try:
        case()
    except Exception as e:  # a test bug or a hang: report and go on
        check(False, f"{case.__name__}: {type(e).__name__}: {e}")
print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
