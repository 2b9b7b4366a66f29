"""The view in a real browser: headless Chromium shows the arm and the cubes where
they are, and follows the arm when it moves.

Each test serves the view of the simulated OpenManipulator-X with 001's board
scene (``board_001``: a board of sockets and three cubes), opens it in Debian's Chromium (software WebGL), and reads the page's
camera back from the page itself; every object's expected pixel is its world
position projected through that camera. A pixel "shows" an object when a
pixel within 3 px has the object's hue (shading changes brightness only).
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any

import numpy as np
import pytest
from browser_page import chromium_or_skip, colour_near, decode, project, visible_area

import armkit
from armkit.scene import arm_capsules, load_scene
from armkit.viz import ArmSource, cube_colour
from armkit.viz._arm_shapes import LINK_COLOUR
from armkit.viz.web import Chromium, View
from armkit.viz.web._picture import connected_client, wait_for_camera

WIDTH, HEIGHT = 1280, 800
WAIT = 15.0  # [s] longest wait for the page to show something
BOARD = load_scene("board_001")
CUBE_COLOURS = {c.name: cube_colour(c.name, BOARD) for c in BOARD.cubes}


@dataclass
class Page:
    arm: armkit.Arm
    view: View
    browser: Chromium
    client: Any

    def shot(self) -> np.ndarray:
        return decode(self.browser.screenshot())

    def until(self, shows: Callable[[np.ndarray], bool]) -> np.ndarray:
        """Screenshots until ``shows(image)`` (at most WAIT s); the last image."""
        deadline = time.monotonic() + WAIT
        image = self.shot()
        while not shows(image) and time.monotonic() < deadline:
            time.sleep(0.2)
            image = self.shot()
        return image


@pytest.fixture
def page(tmp_path: Any) -> Iterator[Page]:
    exe = chromium_or_skip()
    with (
        armkit.Arm("openmanipulator_x") as arm,
        View(ArmSource(arm), scene=BOARD, port=0) as view,
        Chromium(WIDTH, HEIGHT, executable=exe) as browser,
    ):
        view.start()
        browser.open(view.url, "document.querySelector('canvas') !== null")
        client = connected_client(view)
        wait_for_camera(view, client)
        yield Page(arm, view, browser, client)
        # the page came from this process alone: nothing was fetched from a network
        outside = [
            u
            for u in browser.requests
            if not u.startswith(("http://127.0.0.1:", "ws://127.0.0.1:", "data:", "blob:"))
        ]
        assert outside == []


def _cube_pixels(page: Page) -> dict[str, tuple[int, int]]:
    out = {}
    for cube in BOARD.cubes:
        top = cube.center + np.array([0.0, 0.0, cube.size / 2 - 0.002])  # the lit top face
        out[cube.name] = project(page.client.camera, top)
    return out


def _link_pixels(page: Page, q: np.ndarray) -> list[tuple[int, int]]:
    caps = arm_capsules(page.arm.model, q)
    long_links = [
        i for i in range(1, len(caps.radii)) if np.linalg.norm(caps.p1[i] - caps.p0[i]) > 0.05
    ]
    return [project(page.client.camera, (caps.p0[i] + caps.p1[i]) / 2) for i in long_links]


def test_page_shows_the_arm_and_the_cubes_where_they_are(page: Page) -> None:
    cubes = _cube_pixels(page)
    links = _link_pixels(page, page.arm.driver.read())
    image = page.shot()
    assert all(visible_area(image, p) for p in [*cubes.values(), *links]), (
        "camera changed: points hidden"
    )

    def shows_all(img: np.ndarray) -> bool:
        return all(colour_near(img, p, CUBE_COLOURS[n]) for n, p in cubes.items()) and all(
            colour_near(img, p, LINK_COLOUR) for p in links
        )

    image = page.until(shows_all)
    for name, pixel in cubes.items():
        assert colour_near(image, pixel, CUBE_COLOURS[name]), f"{name} not drawn at {pixel}"
    for pixel in links:
        assert colour_near(image, pixel, LINK_COLOUR), f"no link drawn at {pixel}"
    # and the colours are not everywhere: a corner of the table shows none of them
    corner = project(page.client.camera, (-0.05, 0.3, 0.0))
    assert not any(colour_near(image, corner, c) for c in [LINK_COLOUR, *CUBE_COLOURS.values()])


def test_page_follows_the_arm_when_it_moves(page: Page) -> None:
    page.arm.move_joints([45.0, 20.0, 0.0, 0.0])  # reaching forward-left, across the view
    before_links = _link_pixels(page, page.arm.driver.read())
    first = page.until(lambda img: all(colour_near(img, p, LINK_COLOUR) for p in before_links))
    assert all(colour_near(first, p, LINK_COLOUR) for p in before_links)
    after_q = np.radians([-50.0, -30.0, 20.0, 0.0])  # leaning back, turned right
    page.arm.move_joints(np.degrees(after_q).tolist())
    moved = _link_pixels(page, after_q)
    # where the links are now was table before, and is arm now
    assert all(visible_area(first, p) for p in moved)
    assert not any(colour_near(first, p, LINK_COLOUR) for p in moved), "the test's poses overlap"
    image = page.until(lambda img: all(colour_near(img, p, LINK_COLOUR) for p in moved))
    for pixel in moved:
        assert colour_near(image, pixel, LINK_COLOUR), f"the page did not follow the arm to {pixel}"
    assert not any(colour_near(image, p, LINK_COLOUR) for p in before_links[-1:])


def test_in_ci_a_missing_chromium_fails_instead_of_skipping(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    import browser_page

    monkeypatch.setattr(browser_page, "find_chromium", lambda: None)
    monkeypatch.setenv("CI", "true")
    with pytest.raises(pytest.fail.Exception, match="missing in CI"):
        browser_page.chromium_or_skip()
    monkeypatch.setenv("CI", "")
    with pytest.raises(pytest.skip.Exception):
        browser_page.chromium_or_skip()
