"""Output paths: checked before any work, written whole or not at all, devices and FIFOs
written in place (never replaced), symlinks written through."""

from __future__ import annotations

import os
import stat
import subprocess
import threading

import pytest
from conftest import EXAMPLES, run_physc

R = EXAMPLES / "paper" / "04_R.phys"
ALL = EXAMPLES / "paper" / "all.paper.phys"


def test_a_fifo_is_written_in_place(tmp_path):
    fifo = tmp_path / "out.fifo"
    os.mkfifo(fifo)
    received = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_bytes()))
    reader.start()
    run = run_physc("compile", R, "--emit", "qsr", "-o", fifo)
    reader.join(timeout=30)
    assert run.status == 0, run.stderr
    assert stat.S_ISFIFO(fifo.stat().st_mode)
    assert received and received[0].startswith(b"{")


@pytest.mark.skipif(os.geteuid() != 0, reason="making a device node needs root")
def test_a_device_is_written_in_place(tmp_path):
    null = tmp_path / "null"
    os.mknod(null, stat.S_IFCHR | 0o666, os.makedev(1, 3))  # a /dev/null of our own
    run = run_physc("compile", R, "--emit", "qsr", "-o", null)
    assert run.status == 0, run.stderr
    assert stat.S_ISCHR(null.stat().st_mode)


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full")
def test_a_full_device_is_a_clear_error():
    run = run_physc("compile", R, "--emit", "qsr", "-o", "/dev/full")
    assert run.status == 2
    assert "cannot write /dev/full: No space left on device" in run.stderr
    assert stat.S_ISCHR(os.stat("/dev/full").st_mode)


def test_a_symlink_is_written_through(tmp_path):
    target = tmp_path / "real.json"
    target.write_text("old")
    link = tmp_path / "link.json"
    link.symlink_to(target)
    run = run_physc("compile", R, "--emit", "qsr", "-o", link)
    assert run.status == 0, run.stderr
    assert link.is_symlink() and target.read_text().startswith("{")


@pytest.mark.parametrize("option", ["-o", "--task", "--png"])
def test_unwritable_outputs_are_refused_before_the_work(option, tmp_path):
    folder = tmp_path / "folder"
    folder.mkdir()
    run = run_physc("compile", R, option, folder)
    assert run.status == 2
    assert f"cannot write {folder}: it is a directory" in run.stderr
    assert "generating" not in run.stderr  # no work was started
    run = run_physc("compile", R, option, tmp_path / "missing" / "out.xml")
    assert run.status == 2 and "no folder" in run.stderr and "generating" not in run.stderr


def test_several_scenarios_and_one_file_name(tmp_path):
    run = run_physc("compile", ALL, "-s", "SF", "-s", "R", "--png", tmp_path / "layout.png", "-o", tmp_path / "levels")
    assert run.status == 2
    assert "--png must name a folder" in run.stderr
    assert not (tmp_path / "layout.png").exists() and not (tmp_path / "levels").exists()


def test_svg_pictures_are_byte_reproducible(tmp_path):
    for name in ("one.svg", "two.svg"):
        run = run_physc("compile", R, "--emit", "layout", "-o", tmp_path / "layout.json", "--png", tmp_path / name)
        assert run.status == 0, run.stderr
    assert (tmp_path / "one.svg").read_bytes() == (tmp_path / "two.svg").read_bytes()


def test_an_immutable_file_is_refused_before_the_work(tmp_path):
    """Root may write anything its permissions say, but not an immutable file (chattr +i):
    tried before the work, not found after it."""
    target = tmp_path / "out.xml"
    target.write_text("old")
    if subprocess.run(["chattr", "+i", str(target)], capture_output=True).returncode != 0:
        pytest.skip("chattr +i is not allowed here")
    try:
        run = run_physc("compile", R, "-o", target)
        assert run.status == 2 and f"cannot write {target}" in run.stderr and "generating" not in run.stderr
    finally:
        subprocess.run(["chattr", "-i", str(target)], check=True)
    assert target.read_text() == "old"
