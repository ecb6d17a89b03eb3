#!/usr/bin/env bash
# make lab-handout DIR=path [COURSE=folder]: writes the lab kit's student folder (docs/lab.md):
# the stubs of lab/steps, a CMakeLists.txt and Makefile that build them with this clone's lab
# pipeline, checks and viewer, and the README with the steps. No solution goes into it.
set -euo pipefail

dir=${1:-}
if [[ -z "$dir" ]]; then
    echo "usage: make lab-handout DIR=path [COURSE=course-data-folder]" >&2
    exit 2
fi
clone=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
course=${2:-$clone/../shared/data/course}
if [[ ! -f "$course/example0.scene" ]]; then
    echo "lab-handout: no course data in '$course' (example0.scene missing); pass COURSE=folder" >&2
    exit 2
fi
course=$(cd "$course" && pwd)
if [[ -e "$dir" && -n "$(ls -A "$dir" 2>/dev/null)" ]]; then
    echo "lab-handout: '$dir' exists and is not empty; choose a new folder" >&2
    exit 2
fi

mkdir -p "$dir/steps"
cp "$clone"/lab/steps/*.cpp "$dir/steps/"
subst() { sed -e "s|@FACET_SOURCE@|$clone|g" -e "s|@COURSE_DIR@|$course|g" "$1"; }
subst "$clone/lab/handout/CMakeLists.txt.in" >"$dir/CMakeLists.txt"
subst "$clone/lab/handout/Makefile.in" >"$dir/Makefile"
subst "$clone/lab/handout/README.md.in" >"$dir/README.md"
echo "lab-handout: wrote $(cd "$dir" && pwd) (steps/, README.md; 'make lab-check' there to start)"
