# Every target that starts a node keeps DDS discovery on this machine.
export ROS_AUTOMATIC_DISCOVERY_RANGE := LOCALHOST
export ROS_DOMAIN_ID ?= $(shell python3 -c "import random; print(random.randint(1, 100))")

VENV ?= .venv
PYTHON := $(VENV)/bin/python
EXAMPLE := examples/camera_node

.PHONY: venv browser demo demo-arm tour test check lint typecheck golden docs bench bench-quick bench-profile clean

$(VENV)/.installed: pyproject.toml
	python3 -m venv $(VENV)
	$(PYTHON) -m pip install --quiet --upgrade pip
	$(PYTHON) -m pip install --quiet -e ".[test]"
	touch $@

venv: $(VENV)/.installed

## The browser tests of `genparams tune` drive Debian's Chromium (Playwright's own download is not used).
browser:
	@test -x /usr/bin/chromium || (apt-get update && apt-get install -y chromium)

## Generate the example's module and run the demo: a node in its own process, tuned over services.
demo: venv
	cd $(EXAMPLE) && ../../$(VENV)/bin/genparams generate
	$(PYTHON) $(EXAMPLE)/demo.py

## Mapped parameters on a real node: add a key at run time, try a bad one (examples/arm).
demo-arm: venv
	$(PYTHON) examples/arm/demo.py

## Rules, several classes, threads, remote access, lifecycle nodes (examples/motion); PART=rules picks one.
tour: venv
	$(PYTHON) examples/motion/tour.py $(PART)

## Lint, type-check (package, examples and generated code) and run every test.
test: venv browser lint typecheck
	$(PYTHON) -m pytest -q

lint: venv
	$(PYTHON) -m ruff check .
	$(PYTHON) -m ruff format --check genparams tests examples bench
	$(VENV)/bin/lint-imports

typecheck: venv
	$(PYTHON) -m mypy genparams bench
	cd $(EXAMPLE) && ../../$(PYTHON) -m mypy --config-file ../../pyproject.toml camera_node demo.py

## Rewrite the golden files (generated modules, bad-schema errors, docs, check-params reports) after an intended change of output.
golden: venv
	$(PYTHON) -m tests.update_golden

## The documentation site from docs/ (Sphinx + MyST) into build/docs/html; any warning fails.
docs: venv
	$(PYTHON) -m sphinx -W --keep-going -b html docs build/docs/html

## Benchmarks against hand-written rclpy at 10 to 10,000 parameters: docs/benchmarks.md and .csv.
bench: venv browser
	$(PYTHON) -m bench
	$(PYTHON) -m bench.tune

## The benchmarks up to 1,000 parameters with three repeats, into build/bench-quick/.
bench-quick: venv
	$(PYTHON) -m bench --quick

## Where the time of a declare and of one set goes, at 100 and 1,000 parameters (docs/benchmarks-profile.md).
bench-profile: venv
	$(PYTHON) -m bench.profile

clean:
	rm -rf $(VENV) build dist .mypy_cache .ruff_cache .pytest_cache
