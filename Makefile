# The two commands of the README: `make serve` (build and serve the app) and `make test`
# (every check and test). Both install what they need first (scripts/setup.sh).
SHELL := /bin/bash
PORT ?= 8000
export PATH := $(HOME)/.cargo/bin:$(CURDIR)/node_modules/.bin:$(PATH)

.PHONY: serve test setup dist dist-dev bench check-lerobot

## Build the release app into dist/ and serve it on http://127.0.0.1:$(PORT)/
serve: setup dist
	node scripts/serve.mjs dist $(PORT)

## fmt, clippy (native + wasm32), native tests, wasm tests under Node, browser end-to-end tests
test:
	scripts/setup.sh --browser
	scripts/test.sh

setup:
	scripts/setup.sh

dist:
	scripts/build-dist.sh

dist-dev:
	scripts/build-dist.sh --dev

## Speed figures against their budgets: kernels natively and as wasm in Node, the app's size and
## first frame, then every page bench of tests/bench/ in headless Chromium
bench:
	scripts/setup.sh --browser
	scripts/bench.sh

## Not part of `make test`: LeRobot itself (installed with torch into .venv-lerobot, about
## 8 GB the first time) loads the dataset `bsv so101-dataset` writes, offline, every frame
check-lerobot:
	scripts/check-lerobot.sh
