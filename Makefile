# Two commands for a new user: `make demo` and `make test`.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
DEVSTAMP := $(VENV)/.installed-dev
DOCSTAMP := $(VENV)/.installed-docs

.PHONY: demo test lint docs bench clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

KERNEL := setup.py src/armkit/kinematics/_numeric/_lmc.c src/armkit/kinematics/_boundaryc.c  # compiled by pip install -e

$(STAMP): $(BIN)/python pyproject.toml $(KERNEL)  # the demo's own environment: its hints need plot and web
	$(BIN)/python -m pip install --quiet -e ".[plot,web]"
	touch $(STAMP)

$(DEVSTAMP): $(BIN)/python pyproject.toml $(KERNEL)
	$(BIN)/python -m pip install --quiet -e ".[dev]"
	touch $(DEVSTAMP) $(STAMP)

$(DOCSTAMP): $(BIN)/python pyproject.toml $(KERNEL)
	$(BIN)/python -m pip install --quiet -e ".[docs]"
	touch $(DOCSTAMP) $(STAMP)

demo: $(STAMP)
	$(BIN)/armkit demo

lint: $(DEVSTAMP)
	$(BIN)/ruff check src tests benchmarks examples docs/_hooks
	$(BIN)/ruff format --check src tests benchmarks examples docs/_hooks
	$(BIN)/mypy

# The suite on every core (pytest-xdist), the ten slowest tests listed at the end;
# ARMKIT_PROFILE=ci (.ci/run) runs the full fuzz and property budgets (tests/budget.py).
test: lint
	$(BIN)/python -m pytest -n auto --dist worksteal --durations=10

# The documentation site (mkdocs.yml, docs/): --strict fails on any broken link or reference.
docs: $(DOCSTAMP)
	NO_MKDOCS_2_WARNING=1 $(BIN)/mkdocs build --strict

bench: $(DEVSTAMP)
	$(BIN)/python benchmarks/kinematics.py
	$(BIN)/python benchmarks/ik_peers.py
	$(BIN)/python benchmarks/paths.py
	$(BIN)/python benchmarks/bus.py
	$(BIN)/python benchmarks/owi_drift.py
	$(BIN)/python benchmarks/sim.py
	$(BIN)/python benchmarks/view.py
	$(BIN)/python benchmarks/shell.py
	$(BIN)/python benchmarks/music.py
	$(BIN)/python benchmarks/drawing.py
	$(BIN)/python benchmarks/tasks.py
	$(BIN)/python benchmarks/physics.py

clean:
	rm -rf $(VENV) site build *.egg-info src/*.egg-info .pytest_cache .mypy_cache .ruff_cache
	rm -f src/armkit/kinematics/_numeric/*.so src/armkit/kinematics/*.so
