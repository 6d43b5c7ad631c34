// bench_core's main: runs the registered benchmarks as Google Benchmark does, and with --report=FILE.md also writes
// the numbers as a Markdown report with the machine named (cores, CPU model, compiler), a power-law fit of the solve
// time against N with a plot (FILE's stem + "-ordinates.png"), the per-mode split of the default solve naming the
// part that dominates, the Monte Carlo time to the solver's accuracy measured in the same run with the speed-up,
// and the memory of the tables per material.
#pragma once

namespace skinlayer::bench {

int run_benchmarks_with_report(int argc, char** argv);

}  // namespace skinlayer::bench
