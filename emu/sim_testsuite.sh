#!/usr/bin/env bash
# Runs the GNU Blackfin simulator's own testsuite (gdb's sim/testsuite/bfin, shipped in the
# toolchain prefix) against our bfin-elf toolchain and bfin-elf-run, without DejaGnu.
#
#   emu/sim_testsuite.sh [--prefix DIR] [-j N] [-v] [TEST...]
#
#   --prefix DIR  toolchain prefix (default: what emu/bootstrap.sh --print-prefix prints)
#   -j N          run N tests at once (default: nproc)
#   -v            print every test's result, and the commands and output of failing ones
#   --sim-options OPTS
#                 add OPTS to every simulator run, after the test's own '# sim:' options (for
#                 example '--timing bf537': the suite under the BF537 timing model; the
#                 tests listed in emu/sim_testsuite.l1code then run from L1 instruction SRAM)
#   TEST...       test file names in the suite (shell patterns allowed, e.g. 'c_dsp32*'),
#                 or paths to test files; default: the whole suite
#
# Each test is built and run the way sim/testsuite/lib/sim-defs.exp (run_sim_test) does it,
# honouring its header lines (mach, as, ld, cc, sim, progopts, output, status, xerror, timeout,
# requires). Tests known to fail are listed, with the reason, in emu/sim_testsuite.xfail.
# Exit status: 0 when nothing failed unexpectedly and no listed test passed, 1 otherwise,
# 2 for bad arguments or a missing toolchain.
set -uo pipefail
export LC_ALL=C # glob and sort order must match Tcl's lsort, and tool messages stay English

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
me=${0##*/}
xfail_file="$here/sim_testsuite.xfail"

die() { printf '%s: %s\n' "$me" "$*" >&2; exit 2; }
die_usage() { die "$* (try --help)"; }

prefix="" jobs="" verbose=0 sim_extra="" args=()
while (($#)); do
  case $1 in
    -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "${BASH_SOURCE[0]}"; exit 0 ;;
    --prefix) (($# >= 2)) || die_usage "--prefix needs a directory"; prefix=$2; shift ;;
    --prefix=*) prefix=${1#--prefix=} ;;
    -j) (($# >= 2)) || die_usage "-j needs a number"; jobs=$2; shift ;;
    -j*) jobs=${1#-j} ;;
    --jobs=*) jobs=${1#--jobs=} ;;
    -v|--verbose) verbose=1 ;;
    --sim-options) (($# >= 2)) || die_usage "--sim-options needs a value"; sim_extra=$2; shift ;;
    --sim-options=*) sim_extra=${1#--sim-options=} ;;
    --) shift; args+=("$@"); break ;;
    -*) die_usage "unknown option '$1'" ;;
    *) args+=("$1") ;;
  esac
  shift
done
[[ -z $jobs ]] && jobs=$(nproc)
[[ $jobs =~ ^[1-9][0-9]*$ ]] || die_usage "-j wants a positive number, not '$jobs'"
if [[ -z $prefix ]]; then
  prefix=$("$here/bootstrap.sh" --print-prefix) || die "emu/bootstrap.sh --print-prefix failed"
fi
[[ -x $prefix/bin/bfin-elf-run && -x $prefix/bin/bfin-elf-as ]] ||
  die "no bfin-elf toolchain in '$prefix' (build it with emu/bootstrap.sh)"
prefix=$(cd "$prefix" && pwd)
suite="$prefix/share/bfin-sim-testsuite"
[[ -f $suite/testutils.inc ]] || die "no simulator testsuite in '$suite'"

# Upstream globs *.[csS] in the suite directory; a file without a '# mach:' line is skipped
# later, as upstream does, rather than here, so a named test is still checked.
tests=()
if ((${#args[@]} == 0)); then
  tests=("$suite"/*.[csS])
else
  for a in "${args[@]}"; do
    if [[ $a == */* ]]; then
      [[ -f $a ]] || die_usage "no such test file '$a'"
      tests+=("$(cd "$(dirname "$a")" && pwd)/${a##*/}")
    else
      shopt -s nullglob
      # shellcheck disable=SC2206 # $a is a pattern on purpose
      m=("$suite"/$a)
      shopt -u nullglob
      found=()
      for f in "${m[@]}"; do [[ $f == *.[csS] && -f $f ]] && found+=("$f"); done
      ((${#found[@]})) || die_usage "no test '$a' in $suite"
      tests+=("${found[@]}")
    fi
  done
fi

# Each test builds in a directory named after its file, so one name must mean one file.
declare -A seen_name=()
uniq_tests=()
for t in "${tests[@]}"; do
  n=${t##*/}
  if [[ -v seen_name[$n] ]]; then
    [[ ${seen_name[$n]} == "$t" ]] || die_usage "two tests named '$n': ${seen_name[$n]} and $t"
    continue
  fi
  seen_name[$n]=$t
  uniq_tests+=("$t")
done
tests=("${uniq_tests[@]}")

# Test lists: "<test file>  <reason>" a line; blank lines and '#' lines are comments.
# read_test_list FILE ARRAY: ARRAY[test file] = reason, each test checked to be in the suite.
read_test_list() {
  local file=$1 line n=0
  local -n list=$2
  while IFS= read -r line || [[ -n $line ]]; do
    n=$((n + 1))
    [[ $line =~ ^[[:space:]]*(#|$) ]] && continue
    [[ $line =~ ^([^[:space:]]+)[[:space:]]+([^[:space:]].*)$ ]] ||
      die "$file:$n: want '<test file> <reason>', got '$line'"
    [[ -f $suite/${BASH_REMATCH[1]} ]] || die "$file:$n: no test '${BASH_REMATCH[1]}' in the suite"
    list[${BASH_REMATCH[1]}]=${BASH_REMATCH[2]}
  done <"$file"
}

# Expected failures.
declare -A xfail=()
[[ -f $xfail_file ]] && read_test_list "$xfail_file" xfail

# Under a timing model, the tests in sim_testsuite.l1code are linked with their code in L1
# instruction SRAM, where a core fetches at full speed, as their expectations assume (the
# reasons are in the file).
declare -A l1code_list=()
l1code_file="$here/sim_testsuite.l1code"
if [[ $sim_extra =~ --timing[=[:space:]]+bf537 && -f $l1code_file ]]; then
  read_test_list "$l1code_file" l1code_list
fi
l1code=" ${!l1code_list[*]} "

work=$(mktemp -d "${TMPDIR:-/tmp}/sim_testsuite.XXXXXX") || exit 2
runner_pid=""
trap 'rm -rf "$work"' EXIT
interrupted() { [[ -n $runner_pid ]] && kill "$runner_pid" 2>/dev/null; exit "$1"; }
trap 'interrupted 130' INT
trap 'interrupted 143' TERM
mkdir "$work/t" "$work/r"

# ---------------------------------------------------------------------------------------------
# Per-test worker, run in a child bash by xargs. Writes "$work/r/<name>" as
# "<VERDICT>\t<detail>" and keeps its commands and output in "$work/t/<name>/log".

# Converts a Tcl [string match] pattern to a bash one. Everything but * ? [...] and \x is
# quoted, since [[ == ]] matches as if extglob were on and would treat "!(" "+(" specially;
# a leading ! or ^ in a bracket is moved, as Tcl has no negated sets. The result goes to
# $REPLY: command substitution would eat an escaped trailing newline.
tcl_glob_to_bash() {
  local p=$1 out="" c i=0 n=${#1} set
  while ((i < n)); do
    c=${p:i:1}
    case $c in
      '*' | '?') out+=$c ;;
      \\) i=$((i + 1)); out+="\\${p:i:1}" ;;
      '[')
        set=${p:i+1}
        if [[ $set == *']'* ]]; then
          set=${set%%]*}
          i=$((i + ${#set} + 1))
          [[ $set == [!^]* ]] && set="${set:1}${set:0:1}"
          out+="[$set]"
        else
          out+='\['
        fi
        ;;
      *) out+="\\$c" ;;
    esac
    i=$((i + 1))
  done
  REPLY=$out
}

# Runs a command under the time limit, appending the command and its output to the log;
# sets $cmd_rc and $cmd_out.
run_logged() {
  local limit=$1 start=$SECONDS
  shift
  printf '$ %s\n' "$*" >>"$log"
  timeout -k 5 "$limit" "$@" </dev/null >"$dir/out" 2>&1
  cmd_rc=$?
  cmd_timed_out=0
  # 124 (or 137 after -k) is also an ordinary exit status, so the clock has the last word.
  ((cmd_rc == 124 || cmd_rc == 137)) && ((SECONDS - start >= limit)) && cmd_timed_out=1
  # Command substitution drops trailing newlines, which the expected output cares about.
  cmd_out=$(tr -d '\r' <"$dir/out"; printf x)
  cmd_out=${cmd_out%x}
  printf '%s' "$cmd_out" >>"$log"
  printf '[exit status %d]\n' "$cmd_rc" >>"$log"
}

one_line() { # squeezes text into a short single line for the summary
  local s=${1//"$ST_SUITE/"/}
  s=${s//"$ST_PREFIX/"/}
  s=${s//$'\n'/\\n}
  ((${#s} > 160)) && s="${s:0:160}..."
  printf '%s' "$s"
}

run_test() {
  local src=$1 name=${1##*/}
  local dir="$ST_WORK/t/$name" res="$ST_WORK/r/$name" bin="$ST_PREFIX/bin/bfin-elf"
  local log="$dir/log"
  if ! mkdir -p "$dir" || ! cd "$dir"; then
    printf 'UNRESOLVED\tcannot create %s\n' "$dir" >"$res"
    return 0
  fi
  verdict() { printf '%s\t%s\n' "$1" "$2" >"$res"; }

  # slurp_options: "# name(machs): value" lines, trimmed; anything may precede the first
  # one, and the first line that is not one ends them. $srcdir/$subdir name the suite.
  local -A opt=([as]="" [ld]="" [cc]="" [sim]="" [progopts]="" [progos]="" [status]=0
    [output]="" [mach]="" [timeout]="" [xerror]=no [xfail]="" [kfail]="")
  local -A optm=()
  local -a requires=()
  local line oname machs val m seen=0 seen_output=0
  local re='^#[ 	]*([a-zA-Z]*)\(?([^):]*)\)?[ 	]*:[ 	]*(.*)$'
  while IFS= read -r line || [[ -n $line ]]; do
    line=${line#"${line%%[![:space:]]*}"}
    line=${line%"${line##*[![:space:]]}"}
    if [[ $line =~ $re ]]; then
      oname=${BASH_REMATCH[1]} machs=${BASH_REMATCH[2]} val=${BASH_REMATCH[3]}
      # shellcheck disable=SC2016 # the literal words $pwd, $srcdir, $subdir
      {
        val=${val//'$pwd'/$dir}
        val=${val//'$srcdir'/${ST_SUITE%/*}}
        val=${val//'$subdir'/${ST_SUITE##*/}}
      }
      seen=1
      [[ -n $oname && (-v opt[$oname] || $oname == requires) ]] || {
        verdict UNRESOLVED "unknown header option '$oname'"
        return 0
      }
      case $oname in
        output) val="${opt[output]}$val" seen_output=1 ;;
        xfail | kfail) val="${opt[$oname]} $val" ;;
        requires) requires+=("$val"); continue ;;
      esac
      if [[ -z ${machs//[[:space:]]/} ]]; then
        opt[$oname]=$val
      else
        for m in $machs; do [[ $m == bfin ]] && optm[$oname]=$val; done
      fi
    elif ((seen)); then
      break
    fi
  done <"$src"

  local mach_ok=0
  for m in ${opt[mach]}; do [[ $m == bfin || $m == all ]] && mach_ok=1; done
  if ((!mach_ok)); then
    if [[ -z ${opt[mach]} ]]; then
      verdict SKIP "no '# mach:' header, so not a test"
    else
      verdict SKIP "not for mach bfin ('# mach: ${opt[mach]}')"
    fi
    return 0
  fi
  # Upstream compares progos with the C library its compiler check found; ours has none.
  if [[ -n ${opt[progos]} ]]; then
    verdict UNTESTED "needs a '${opt[progos]}' C library; the toolchain is freestanding"
    return 0
  fi
  local req what
  for req in "${requires[@]}"; do
    read -r what val <<<"$req"
    case $what in
      simoption)
        # sim_check_requires_simoption: "  --opt" then a space or '[' on a line of --help.
        if [[ $'\n'$("$bin-run" --help 2>&1) != *$'\n'"  $val"[\[\ ]* ]]; then
          verdict UNTESTED "simulator lacks option $val"
          return 0
        fi
        ;;
      *) verdict UNRESOLVED "unknown requirement '$what'"; return 0 ;;
    esac
  done

  local k
  for k in as ld cc sim; do [[ -v optm[$k] ]] && opt[$k]=${optm[$k]}; done
  if ((!seen_output)); then
    [[ ${opt[xerror]} == no ]] && opt[output]=$'pass\n' || opt[output]=$'fail\n'
  fi
  opt[output]=${opt[output]//\\n/$'\n'}

  local limit=${opt[timeout]:-$ST_TIMEOUT}
  local -a as_opts ld_opts cc_opts sim_opts prog_opts wa=() wl=()
  # A test of ours may include files beside it (emu/tests/dma/mdma.inc).
  read -ra as_opts <<<"${opt[as]} -I$ST_SUITE -I${src%/*}"
  read -ra ld_opts <<<"${opt[ld]}"
  [[ $ST_L1CODE == *" ${src##*/} "* ]] && ld_opts+=(-Ttext=0xFFA00000)
  read -ra cc_opts <<<"${opt[cc]}"
  read -ra sim_opts <<<"${opt[sim]} $ST_SIM_EXTRA"
  read -ra prog_opts <<<"${opt[progopts]}"
  # sim-defs.exp means to pass every as/ld option through gcc with -Wa,/-Wl, (its regsub
  # lacks -all, so it only prefixes the first; no test has more than one).
  for k in "${as_opts[@]}"; do wa+=("-Wa,$k"); done
  for k in "${ld_opts[@]}"; do wl+=("-Wl,$k"); done

  # No -mcpu: allinsn.exp's -mcpu=bf537 only reaches sim-defs.exp's toolchain probes, and
  # with it gcc predefines __ADSPBF537__, which test.h then redefines for .S files (a warning,
  # so a failure). -lm is what DejaGnu's target_compile adds to every executable.
  local stage
  case $src in
    *.c)
      stage=compiling/linking
      run_logged "$limit" "$bin-gcc" "$src" -I"$ST_SUITE" "${wa[@]}" "${wl[@]}" "${cc_opts[@]}" \
        -lm -o "$name.x"
      ;;
    *.S)
      stage=compiling
      run_logged "$limit" "$bin-gcc" "$src" -I"$ST_SUITE" "${wa[@]}" -c -o "$name.o"
      ;;
    *)
      stage=assembling
      run_logged "$limit" "$bin-as" "$src" "${as_opts[@]}" -o "$name.o"
      ;;
  esac
  # target_compile counts any diagnostic as failure, so a warning fails the test as upstream.
  if ((cmd_rc != 0)) || [[ -n $cmd_out ]]; then
    verdict FAIL "($stage) $(one_line "$cmd_out")"
    return 0
  fi
  if [[ $src != *.c ]]; then
    stage=linking
    run_logged "$limit" "$bin-ld" "$name.o" "${ld_opts[@]}" -o "$name.x"
    if ((cmd_rc != 0)) || [[ -n $cmd_out ]]; then
      verdict FAIL "($stage) $(one_line "$cmd_out")"
      return 0
    fi
  fi

  run_logged "$limit" "$bin-run" "${sim_opts[@]}" "$name.x" "${prog_opts[@]}"
  if ((cmd_timed_out)); then
    verdict FAIL "(execution) timed out after $limit s; output: $(one_line "$cmd_out")"
    return 0
  fi
  if ((cmd_rc == 77)); then
    verdict UNSUPPORTED "(execution) exit status 77 means unsupported"
    return 0
  fi
  local status_ok=0 output_ok=0 REPLY
  [[ $cmd_rc == "${opt[status]}" ]] && status_ok=1
  tcl_glob_to_bash "${opt[output]}"
  # shellcheck disable=SC2053 # a pattern on purpose
  [[ $cmd_out == $REPLY ]] && output_ok=1
  local got
  got="exit status $cmd_rc, output '$(one_line "$cmd_out")'"
  if [[ ${opt[xerror]} == no ]]; then
    if ((status_ok && output_ok)); then
      verdict PASS ""
    elif ((status_ok)); then
      verdict FAIL "(execution) $got, expected output '$(one_line "${opt[output]}")'"
    else
      verdict FAIL "(execution) $got, expected exit status ${opt[status]}"
    fi
  else
    if ((status_ok)); then
      verdict FAIL "(execution) $got, expected a failure exit status (xerror)"
    elif ((output_ok)); then
      verdict PASS ""
    else
      verdict FAIL "(execution) $got, expected output '$(one_line "${opt[output]}")' (xerror)"
    fi
  fi
  return 0
}

# A test takes well under a second; the limit is only there to stop a hang.
export ST_WORK=$work ST_SUITE=$suite ST_PREFIX=$prefix ST_TIMEOUT=60 ST_SIM_EXTRA=$sim_extra ST_L1CODE=$l1code
export -f run_test run_logged tcl_glob_to_bash one_line

start=$SECONDS
# shellcheck disable=SC2016 # $1 is the child's
printf '%s\0' "${tests[@]}" |
  xargs -0 -n 1 -P "$jobs" bash -c 'run_test "$1"' run_test &
runner_pid=$!
wait "$runner_pid"
runner_pid=""

# ---------------------------------------------------------------------------------------------
passed=0 xfailed=0 failed=0 xpassed=0 skipped=0
while IFS= read -r src; do
  name=${src##*/}
  if [[ -f $work/r/$name ]]; then
    IFS=$'\t' read -r v detail <"$work/r/$name"
  else
    v=UNRESOLVED detail="the runner left no result"
  fi
  reason=${xfail[$name]-}
  case $v in
    SKIP)
      skipped=$((skipped + 1))
      # Silent in a full run: upstream skips such files without a word, too.
      ((verbose || ${#args[@]})) && printf 'SKIP: %s: %s\n' "$name" "$detail"
      continue
      ;;
    PASS)
      if [[ -n $reason ]]; then
        xpassed=$((xpassed + 1))
        printf 'XPASS: %s (listed as expected failure: %s)\n' "$name" "$reason"
      else
        passed=$((passed + 1))
        ((verbose)) && printf 'PASS: %s\n' "$name"
      fi
      ;;
    *)
      if [[ -n $reason ]]; then
        xfailed=$((xfailed + 1))
        ((verbose)) && printf 'XFAIL: %s: %s [%s %s]\n' "$name" "$reason" "$v" "$detail"
      else
        failed=$((failed + 1))
        printf '%s: %s %s\n' "$v" "$name" "$detail"
        ((verbose)) && [[ -f $work/t/$name/log ]] && sed 's/^/    /' "$work/t/$name/log"
      fi
      ;;
  esac
done < <(printf '%s\n' "${tests[@]}")

total=$((passed + xfailed + failed + xpassed))
((verbose)) && printf '%d file(s) skipped (not for mach bfin); %d s with -j %d\n' \
  "$skipped" $((SECONDS - start)) "$jobs"
printf 'sim testsuite: %d passed, %d expected failures, %d unexpected failures, %d unexpected passes (of %d)\n' \
  "$passed" "$xfailed" "$failed" "$xpassed" "$total"
((failed == 0 && xpassed == 0))
