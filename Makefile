# The two commands of the README. Both install what is missing (Debian 12 packages), then build.
BUILD ?= build
MPIRUN ?= mpirun
# Root needs OpenMPI's explicit consent; --oversubscribe lets 2 ranks run on a 1-core machine; shared
# memory only (no probing for network transports) saves about 0.2 s of start-up on one machine.
MPIRUN_FLAGS ?= $(if $(filter 0,$(shell id -u)),--allow-run-as-root,) --oversubscribe --mca pml ob1 --mca btl self,vader

PREFIX ?= /usr/local

.PHONY: demo test build program install deb web-deps deps bench bench-ltc bench-brdf bench-ebrdf bench-cluster soak clean \
        test-sanitize test-sanitize-unit fuzz

# Builds only the program (the tests and benchmarks are built by `make test`).
demo: program
	$(MPIRUN) $(MPIRUN_FLAGS) -np 2 $(BUILD)/pbrfit run jobs/quickstart.yaml
	@echo
	@$(BUILD)/pbrfit status results/quickstart.h5
	@echo
	@echo "The table is in results/quickstart.h5 (group /dfg; layout in docs/results-lut.md)."
	@echo "Look inside:  h5ls -r results/quickstart.h5   or   h5dump -d /dfg/scale results/quickstart.h5"

test: build web-deps
	.ci/install-deps --slurm || echo "pbrfit: the Slurm packages could not be installed; the cluster test will say it is skipped"
	cd $(BUILD) && { ctest --output-on-failure; status=$$?; \
	  grep -h "^SKIP:" Testing/Temporary/LastTest.log || true; \
	  awk '/ Testing: /{test=$$0} /^FAIL:/{print test ": " $$0}' Testing/Temporary/LastTest.log; exit $$status; }

bench: build
	tests/benchmarks/dfg_lut.sh $(BUILD)/pbrfit
	tests/benchmarks/dfg_threads.sh $(BUILD)/pbrfit
	tests/benchmarks/runtime_state.sh $(BUILD)/tests/pbrfit_runtime_probe
	$(BUILD)/tests/bench_optimizers
	tests/benchmarks/sweep_benchmark.sh $(BUILD)/pbrfit
	tests/benchmarks/symreg_benchmark.sh $(BUILD)/pbrfit
	tests/benchmarks/symreg_heldout.sh $(BUILD)/pbrfit

# Rank 0's rate at 2-16 ranks, every shipped job on 2 ranks (at most 90 s each) and the cluster model's
# predictions at 64, 256 and 1,024 ranks (about 25 minutes on 2 cores); the machine's peak per core.
bench-cluster: build
	tests/benchmarks/cluster_model.sh $(BUILD)
	$(BUILD)/tests/bench_machine_peak

# LTC tables of every built-in BRDF family, beside the published GGX table and the LTC paper's procedure
# (about 20 minutes on 2 cores).
bench-ltc: build
	tests/benchmarks/ltc_families_benchmark.sh $(BUILD)

# The genBRDF searches of jobs/merl-metals.yaml and jobs/merl-dielectrics.yaml (about 2 hours each on 2 cores).
bench-brdf: build
	$(BUILD)/tests/bench_brdf_metric
	tests/benchmarks/brdf_search_benchmark.sh $(BUILD)/pbrfit jobs/merl-metals.yaml
	tests/benchmarks/brdf_search_benchmark.sh $(BUILD)/pbrfit jobs/merl-dielectrics.yaml

# eBRDF prefiltering of the three built-in maps, their renders, the SGD comparison and a 512 x 512 scale run
# (about 45 minutes on 2 cores).
bench-ebrdf: build
	tests/benchmarks/ebrdf_benchmark.sh $(BUILD)

# Fault injection, 20 rounds of each fault (about 15 minutes; not part of test). Figures: docs/RELIABILITY.md.
soak: build
	PBRFIT=$(abspath $(BUILD))/pbrfit PBRFIT_SOURCE_DIR=$(CURDIR) tests/soak/fault_soak.sh 20

# The suite under sanitizers, built with clang in folders of their own (tests/sanitizers/run.sh,
# docs/RELIABILITY.md): ASan + UBSan over every test, then TSan over the unit and in-process runtime tests.
test-sanitize: deps
	.ci/install-deps --clang
	$(MAKE) web-deps BUILD=build-asan
	tests/sanitizers/run.sh address,undefined build-asan all
	$(MAKE) web-deps BUILD=build-tsan
	tests/sanitizers/run.sh thread build-tsan unit

# The ASan + UBSan unit tests alone (CI runs them after `make test`).
test-sanitize-unit: deps
	.ci/install-deps --clang
	$(MAKE) web-deps BUILD=build-asan
	tests/sanitizers/run.sh address,undefined build-asan unit

# A fuzz campaign: every libFuzzer target of tests/fuzz for FUZZ_SECONDS each (default 600), two at a time,
# built with clang, ASan and UBSan in build-fuzz/ (tests/fuzz/run.sh; figures in docs/RELIABILITY.md).
FUZZ_SECONDS ?= 600
fuzz: deps program
	.ci/install-deps --clang
	tests/fuzz/run.sh $(FUZZ_SECONDS)

# The npm packages of the browser and node tests (tests/web/package.json): three.js, playwright-core, ktx-parse.
web-deps:
	.ci/install-deps --web
	@node -e 'process.exit(+process.versions.node.split(".")[0] >= 20 ? 0 : 1)' || \
	  { echo "pbrfit: the web tests need Node.js 20 or later (playwright-core); this is $$(node --version)"; exit 1; }
	mkdir -p $(BUILD)/web && cp tests/web/package.json tests/web/package-lock.json $(BUILD)/web/
	cd $(BUILD)/web && { [ -d node_modules ] && npm ls --silent >/dev/null 2>&1 || npm ci --no-audit --no-fund --loglevel=error; }

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j 2

program: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j 2 --target pbrfit

# docs/install.md: the program and its shared files under PREFIX (bin/, share/pbrfit, share/doc/pbrfit).
install: program
	cmake --install $(BUILD) --prefix $(PREFIX)

# A Debian package of the same files, BUILD/pbrfit_VERSION_ARCH.deb (install it with apt install ./FILE).
deb: program
	cd $(BUILD) && cpack -G DEB

deps:
	.ci/install-deps

clean:
	rm -rf $(BUILD) build-asan build-tsan build-fuzz
