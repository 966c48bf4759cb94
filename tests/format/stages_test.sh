#!/usr/bin/env bash
# The grader's stages talk down, never up (grader/DESIGN.md): a file of grader/ includes only its
# own folder's files, those of the folders ranked below its own, and the framework's. The commands'
# mains (MAINS) sit above every stage. Outside grader/ and
# framework/, only the checks stage may include (it runs the physics suite in this process:
# tests/support/, tests/golden/); KNOWN_OUTSIDE names what else still does, and why, and must
# only shrink. Read from the #include lines of the committed files; nothing is compiled.
#
#   tests/format/stages_test.sh SOURCE_DIR
# Exit code: 0 every include goes down, 1 some do not (each named with its ranks).
set -uo pipefail
cd "$1" || exit 1

# The folders of grader/, lowest first: each may include those before it.
RANKS=(common reference sandbox probe rubric intake build checks mistakes replay scoring report grading
  batch insights)
# The programs' mains: each may include any stage.
MAINS=(grader/main.cpp grader/batch/batch_main.cpp grader/insights/insights_main.cpp
  grader/probe/probe_main.cpp grader/sandbox/keeper_main.cpp)
# Includes from outside grader/ and framework/ that are not the checks stage's, with the reason.
KNOWN_OUTSIDE=()

rank_of() {
  local i
  for i in "${!RANKS[@]}"; do [ "${RANKS[$i]}" = "$1" ] && { echo "$i"; return; }; done
  echo -1
}

# Whether WORD is one of the rest of the arguments (no pipe: under pipefail, grep -q ending
# first would kill printf and turn a match into a failure, by chance, on a loaded machine).
among() {
  local word="$1" item
  shift
  for item in "$@"; do [ "$item" = "$word" ] && return 0; done
  return 1
}

# FILE -> its folder's rank; a program's main ranks above every stage.
file_rank() {
  if among "$1" "${MAINS[@]}"; then
    echo 99
  else
    rank_of "$(cut -d/ -f2 <<<"$1")"
  fi
}

# FILE INCLUDE -> where the include is found: "grader FOLDER", "framework", "system" (an
# <include> found in neither) or "outside".
resolve() {
  local dir found
  dir=$(dirname "$1")
  if [ -f "$dir/$2" ]; then  # beside the file, or reached by a relative path ("../report/...")
    found=$(realpath -m --relative-to=. "$dir/$2")
    case "$found" in
      grader/*/*) echo "grader $(cut -d/ -f2 <<<"$found")" ;;
      framework/*) echo framework ;;
      *) echo outside ;;
    esac
  elif [ -f "grader/$2" ]; then
    echo "grader $(cut -d/ -f1 <<<"$2")"
  elif [ -f "framework/$2" ] || [ -f "framework/include/$2" ]; then
    echo framework
  elif [ "${3:-}" = angle ]; then
    echo system
  else
    echo outside
  fi
}

# FILE INCLUDE -> the problem with that include, or nothing.
problem_of() {
  local file=$1 include=$2 mine theirs where folder
  mine=$(file_rank "$file")
  [ "$mine" -ge 0 ] || { echo "$file: its folder has no rank (add it to RANKS and DESIGN.md)"; return; }
  read -r where folder <<<"$(resolve "$file" "$include" "${3:-}")"
  case "$where" in
    grader)
      theirs=$(rank_of "$folder")
      if [ "$theirs" -lt 0 ]; then
        echo "$file includes $include: grader/$folder/ has no rank"
      elif [ "$theirs" -gt "$mine" ]; then
        echo "$file includes $include: $folder/ ranks above $(cut -d/ -f2 <<<"$file")/"
      fi
      ;;
    outside)
      [[ "$file" == grader/checks/* ]] && return
      among "$file $include" "${KNOWN_OUTSIDE[@]}" ||
        echo "$file includes $include, from outside grader/ and framework/"
      ;;
  esac
}

# The measure itself: an include up and one from tests/ must be found, one down must not.
[ -n "$(problem_of grader/rubric/rubric.cpp checks/checks.h)" ] &&
  [ -n "$(problem_of grader/rubric/rubric.cpp ../checks/checks.h)" ] &&
  [ -n "$(problem_of grader/rubric/rubric.cpp checks/checks.h angle)" ] &&
  [ -n "$(problem_of grader/report/report.cpp suite.h)" ] &&
  [ -n "$(problem_of grader/batch/batch.cpp ../insights/page.h)" ] &&
  [ -z "$(problem_of grader/report/report.cpp checks/outcome.h)" ] &&
  [ -z "$(problem_of grader/report/report.cpp vector angle)" ] ||
  { echo "FAIL: the measure is broken (an include up or from tests/ went unseen)"; exit 1; }

problems=() checked=0
while IFS= read -r file; do
  while read -r include kind; do
    checked=$((checked + 1))
    problem=$(problem_of "$file" "$include" "$kind")
    [ -z "$problem" ] || problems+=("$problem")
  done < <(sed -n -e 's/^[ \t]*#[ \t]*include[ \t]*"\([^"]*\)".*/\1 quoted/p' \
                  -e 's/^[ \t]*#[ \t]*include[ \t]*<\([^>]*\)>.*/\1 angle/p' "$file")
done < <(git ls-files -- 'grader/*.cpp' 'grader/*.h' 'grader/*.inc')

if [ "$checked" -eq 0 ]; then
  echo "FAIL: no #include found in grader/ (not a checkout?)"
  exit 1
fi
if [ "${#problems[@]}" -gt 0 ]; then
  printf '%s\n' "${problems[@]}" | sort -u
  echo "FAIL: ${#problems[@]} includes of grader/ go up or out (the order: ${RANKS[*]})"
  exit 1
fi
echo "ok: $checked includes of grader/ go down (the order: ${RANKS[*]}; the commands' mains above)"
