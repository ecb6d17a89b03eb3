// lab_check: the course's steps in order against facet; exit 0 when every step passes, 1 when
// one does not (the report says which and why), 2 for a bad command line.

#include <cstdio>
#include <string>

#include "lab/checks.hpp"

int main(int argc, char** argv) {
    std::string dir = FACET_LAB_COURSE_DIR;
    if (argc > 2 || (argc == 2 && std::string(argv[1]).rfind('-', 0) == 0)) {
        std::fprintf(stderr, "usage: lab_check [COURSE_DATA_DIR]  (default %s)\n",
                     FACET_LAB_COURSE_DIR);
        return 2;
    }
    if (argc == 2) dir = argv[1];
    std::printf("The course's steps, in order, against facet (course data: %s)\n", dir.c_str());
    const std::vector<lab::StepResult> results = lab::runChecks(dir);
    std::fputs(lab::formatResults(results).c_str(), stdout);
    for (const lab::StepResult& r : results)
        if (r.outcome != lab::Outcome::Passed) return 1;
    return 0;
}
