// The study commands of the command line: `arksph batch` and `arksph study ...` (main.cpp
// dispatches to them). Each returns the process exit code; bad input throws InputError (exit 2).
#pragma once

namespace arksph {

// arksph batch SWEEP.toml [--jobs N] [--out DIR] [--quiet]
int cmd_batch(int argc, char** argv);

// arksph study order STUDY.toml [--out DIR] [--set KEY=VALUE ...]
int cmd_study(int argc, char** argv);

}  // namespace arksph
