// The command line of `arksph study KIND STUDY.toml [--out DIR] [--jobs N] [--set KEY=VALUE ...] [--quiet]`,
// parsed once in app/study_commands.cpp for every kind of study.
#pragma once
#include <string>
#include <vector>

namespace arksph {

struct StudyArgs {
  std::string path;               // the study file
  std::string out;                // --out: overrides the study's output directory when not empty
  std::vector<std::string> sets;  // --set KEY=VALUE, in order
  int jobs = 0;                   // --jobs N; 0: the study file's value
  bool quiet = false;             // --quiet / -q
};

}  // namespace arksph
