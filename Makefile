# Every target that starts a node keeps DDS discovery on this machine.
export ROS_AUTOMATIC_DISCOVERY_RANGE := LOCALHOST
export ROS_DOMAIN_ID ?= $(shell python3 -c "import random; print(random.randint(1, 100))")
# pytest takes a domain no other run on this machine holds (tests/domains.py), unless given one.
FREE_DOMAIN := $(if $(filter file,$(origin ROS_DOMAIN_ID)),env -u ROS_DOMAIN_ID)

VENV ?= .venv
PYTHON := $(VENV)/bin/python
EXAMPLE := examples/camera_node


.PHONY: venv lock test-latest browser demo import-node-demo demo-arm tour test check lint typecheck golden screenshots docs bench bench-targets bench-quick bench-profile import-rates soak mutate mutate-sample clean

# The development environment installs from requirements/dev.txt: every package of every
# extra, the build backend (hatchling, editables) and the dev tools, pinned with their hashes
# for every platform. It names no package index: the machine's own client configuration
# decides where packages come from. uv comes pinned and hashed from requirements/uv.txt;
# genparams goes in editable, without dependencies of its own and without build isolation.
LOCK := requirements/dev.txt
UV := $(VENV)/bin/uv
COMPILE := uv pip compile --quiet --generate-hashes --universal --python-version 3.11

$(VENV)/.installed: pyproject.toml $(LOCK) requirements/uv.txt
	rm -rf "$(VENV)"
	python3 -m venv "$(VENV)"
	"$(PYTHON)" -m pip install --quiet --require-hashes -r requirements/uv.txt
	"$(UV)" pip sync --quiet --python "$(PYTHON)" --require-hashes $(LOCK)
	"$(UV)" pip install --quiet --python "$(PYTHON)" --no-deps --no-build-isolation -e .
	touch "$@"

venv: $(VENV)/.installed

## Refresh the locks on purpose: the newest releases that pyproject.toml's ranges admit.
lock:
	python3 -m venv build/lock-venv
	build/lock-venv/bin/pip install --quiet --require-hashes -r requirements/uv.txt
	build/lock-venv/bin/$(COMPILE) --upgrade --all-extras --group build pyproject.toml -o $(LOCK)
	build/lock-venv/bin/$(COMPILE) --upgrade -o requirements/uv.txt requirements/uv.in

## The whole suite against the newest releases (not the lock), in build/latest-venv:
## breakage by a new release shows here before `make lock` takes it in.
test-latest: browser
	rm -rf build/latest-venv
	python3 -m venv build/latest-venv
	build/latest-venv/bin/pip install --quiet --require-hashes -r requirements/uv.txt
	build/latest-venv/bin/uv pip install --quiet --python build/latest-venv/bin/python \
		--upgrade -e ".[test,tune]"
	$(FREE_DOMAIN) build/latest-venv/bin/python -m pytest -q

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

## A schema read from a running hand-written rclpy node (docs/import-node.md).
import-node-demo: venv
	@$(PYTHON) -m tests.import_node.hand_written_nodes hand_written_driver:driver >/dev/null & \
	node=$$!; $(VENV)/bin/genparams import-node /hand_written_driver --timeout 30; \
	code=$$?; kill $$node; exit $$code

## Lint, type-check (package, tests, examples and generated code) and run every test.
test: venv browser lint typecheck
	$(FREE_DOMAIN) $(PYTHON) -m pytest -q

lint: venv
	$(PYTHON) -m ruff check .
	$(PYTHON) -m ruff format --check genparams tests examples bench
	$(VENV)/bin/lint-imports

typecheck: venv
	$(PYTHON) -m mypy genparams bench tests
	cd $(EXAMPLE) && ../../$(PYTHON) -m mypy --config-file ../../pyproject.toml camera_node demo.py

## The tuning server under page loads, node churn and events: memory and fds stay flat.
## SCALE=10 runs ten times the default (which takes about a minute).
soak: venv
	GENPARAMS_SOAK_SCALE=$(or $(SCALE),1) $(PYTHON) -m pytest -s -q tests/tune/test_tune_soak.py

## Rewrite the golden files (generated modules, bad-schema errors, docs, check-params reports) after an intended change of output.
golden: venv
	$(PYTHON) -m tests.update_golden

## Refresh docs/images/tune.png on purpose: the tuning page on the camera example, in Chromium
## (tests/tune/test_tune_page.py takes it; any other run writes it to a temporary folder).
screenshots: venv browser
	GENPARAMS_SCREENSHOTS="$(CURDIR)/docs/images" $(PYTHON) -m pytest -q -p no:cacheprovider \
		tests/tune/test_tune_page.py -k test_screenshot_for_the_docs

## The documentation site from docs/ (Sphinx + MyST) into build/docs/html; any warning fails.
docs: venv
	$(PYTHON) -m sphinx -W --keep-going -b html docs build/docs/html

## The runtime's targets, then benchmarks against hand-written rclpy at 10 to 10,000 parameters: docs/benchmarks.md and .csv.
bench: venv browser
	$(PYTHON) -m bench
	$(PYTHON) -m bench.tune

## The runtime's targets against hand-written rclpy, each printed MET or MISSED with its spread (~3 min).
bench-targets: venv
	$(PYTHON) -m bench.targets

## The targets with fewer samples, the benchmarks up to 1,000 parameters with three repeats, into build/bench-quick/.
bench-quick: venv
	$(PYTHON) -m bench --quick

## Where the time of a declare and of one set goes, at 100 and 1,000 parameters (docs/benchmarks-profile.md).
bench-profile: venv
	$(PYTHON) -m bench.profile

## import-rclpy's exact-import rate on public rclpy nodes (docs/migrating-from-rclpy.md#measuring-it-again).
## MIRRORS=DIR: bare git copies of the repositories bench/import_rates_data/nodes.yaml names.
import-rates: venv
	$(if $(MIRRORS),,$(error set MIRRORS=DIR, a folder of owner+name git copies))
	$(PYTHON) -m bench.import_rates --mirrors $(MIRRORS) --details

## Mutation testing of the runtime and check-params with mutmut (docs/robustness.md); MODULES=... picks some.
## Results persist in mutants/, so a stopped run resumes; survivors are retried after the first pass.
mutate: venv
	$(PYTHON) -m tests.mutate run $(MODULES)
	$(PYTHON) -m tests.mutate recheck $(MODULES)

## A few minutes of it for CI: SAMPLE mutants that the last full run killed must still be killed.
mutate-sample: venv
	$(PYTHON) -m tests.mutate sample $(or $(SAMPLE),25)

clean:
	rm -rf $(VENV) build dist .mypy_cache .ruff_cache .pytest_cache mutants
