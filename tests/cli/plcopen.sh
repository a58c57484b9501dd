#!/usr/bin/env bash
# PLCopen TC6 XML (docs/iec.md "PLCopen XML"): one mixing program as each producer writes it
# (tests/iec/plcopen/: Beremiz, OpenPLC, CODESYS, TwinCAT, the old tc6.xsd) is read, checked,
# compiled and run. Every file's `gfec run --observable` prints the outputs of mixer.expected
# (worked out by hand from docs/iec.md, scan by scan); the C engine in both forms, fed the same
# inputs, prints what the interpreter printed, activations included; the converted chart text
# (--emit=chart) compiles to the same engine; --check speaks SARIF; -Wplcopen-inferred names the
# convergence TwinCAT leaves out; an ST program of the same meaning runs to the same outputs.
# Usage: plcopen.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$1
caller=$(cd "$(dirname "$0")" && pwd)/engine_caller.py
dir=$2/tests/iec/plcopen
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# Both engine forms of SRC, driven by a caller generated from their header and fed CSV, print
# REFERENCE (what gfec run printed). Arguments after REFERENCE go to gfec (--chart POU).
engines_agree() { # LABEL SRC CSV CHART TICKS REFERENCE [GFEC-ARG...]; TICKS "" for the trace's
  local label=$1 src=$2 csv=$3 chart=$4 ticks=$5 reference=$6 form
  shift 6
  for form in readable scalable; do
    "$gfec" "$src" "$@" --engine=$form -o engine.c
    python3 "$caller" engine.h "$csv" "$chart" $ticks > main.c
    cc -std=c99 -Wall -Wextra -Wpedantic -Werror main.c engine.c -o run || fail "$label: the $form engine does not build"
    ./run > engine.txt
    diff -u "$reference" engine.txt || fail "$label: the $form engine differs from gfec run"
  done
}
cd "$work"


for producer in beremiz openplc codesys twincat tc6_old; do
  src=$dir/$producer.xml
  "$gfec" --check "$src" 2> check.txt || fail "$producer: --check fails: $(cat check.txt)"
  if [[ $producer == twincat ]]; then
    grep -q 'without a selection convergence.*\[-Wplcopen-inferred\]' check.txt ||
      fail "twincat: the missing selection convergence is not reported: $(cat check.txt)"
  else
    [[ ! -s check.txt ]] || fail "$producer: --check says something: $(cat check.txt)"
  fi
  "$gfec" run "$src" --inputs "$dir/mixer.csv" --observable --ticks 14 > run.txt 2> run.err ||
    fail "$producer: gfec run fails: $(cat run.err)"
  grep -v '^av' run.txt > outs.txt
  diff -u "$dir/mixer.expected" outs.txt || fail "$producer: gfec run's outputs differ from mixer.expected"
  engines_agree "$producer" "$src" "$dir/mixer.csv" Mixer 14 run.txt
  # The converted chart text compiles to the same engine.
  rm -rf direct back && mkdir direct back
  "$gfec" --emit=chart "$src" -o back/Mixer.sfc 2> /dev/null
  "$gfec" "$src" --no-line-directives -o direct/engine.c 2> /dev/null
  (cd back && "$gfec" Mixer.sfc --no-line-directives -o engine.c)
  # (line 1 names the file it was generated from)
  cmp <(tail -n +2 direct/engine.c) <(tail -n +2 back/engine.c) ||
    fail "$producer: --emit=chart's text compiles to another engine"
  "$gfec" --check -fdiagnostics-format=sarif-stderr "$src" 2> sarif.json || fail "$producer: --check with SARIF fails"
  grep -q '"version": "2.1.0"' sarif.json || fail "$producer: no SARIF log"
done

# A macro step expanded inline, negated conditions and a jump (macro.xml): the log worked out by
# hand, both engine forms agree, and the converted chart compiles to the same engine.
"$gfec" run "$dir/macro.xml" --inputs "$dir/macro.csv" --observable > macro.txt || fail "macro.xml: gfec run fails"
diff -u "$dir/macro.expected" macro.txt || fail "macro.xml: gfec run differs from macro.expected"
engines_agree "macro.xml" "$dir/macro.xml" "$dir/macro.csv" Press "" macro.txt
rm -rf direct back && mkdir direct back
"$gfec" --emit=chart "$dir/macro.xml" -o back/Press.sfc
"$gfec" "$dir/macro.xml" --no-line-directives -o direct/engine.c
(cd back && "$gfec" Press.sfc --no-line-directives -o engine.c)
cmp <(tail -n +2 direct/engine.c) <(tail -n +2 back/engine.c) || fail "macro.xml: --emit=chart's text compiles to another engine"
# A program's inOutVars are inouts (docs/iec.md): the inputs of macro.xml so declared.
sed 's/inputVars>/inOutVars>/' "$dir/macro.xml" > inout.xml
"$gfec" --emit=chart inout.xml -o inout.sfc || fail "inOutVars: --emit=chart fails"
grep -q '^ *inout bool Start;' inout.sfc && grep -q '^ *inout bool Done;' inout.sfc ||
  fail "inOutVars: not inouts: $(cat inout.sfc)"

# The ST program of the same meaning (written as the ST reader reads it) runs to the same outputs.
"$gfec" run "$dir/mixer.st" --inputs "$dir/mixer.csv" --observable --ticks 14 | grep -v '^av' > st.txt ||
  fail "mixer.st: gfec run fails"
diff -u "$dir/mixer.expected" st.txt || fail "mixer.st runs to other outputs than the PLCopen files"
# The ST reader's mixer (tests/iec/st/mixer.st, its actions' bodies with IF and CASE) as PLCopen
# XML runs to that program's whole log, activations included.
"$gfec" run "$dir/st_mixer.xml" --inputs "$dir/../st/mixer.csv" --observable > st_mixer.txt ||
  fail "st_mixer.xml: gfec run fails"
diff -u "$dir/../st/mixer.expected" st_mixer.txt || fail "st_mixer.xml runs to another log than tests/iec/st/mixer.st"
# Function blocks (docs/iec.md "Function blocks"): tests/iec/st/blocks.st as PLCopen XML, a
# functionBlock POU and <derived> instances, runs to that program's log.
"$gfec" run "$dir/st_blocks.xml" --inputs "$dir/../st/blocks.csv" --observable > st_blocks.txt ||
  fail "st_blocks.xml: gfec run fails"
diff -u "$dir/../st/blocks.expected" st_blocks.txt || fail "st_blocks.xml runs to another log than tests/iec/st/blocks.st"
# SFC inside an action and an SFC function block (docs/iec.md "SFC inside actions and function
# blocks"), as Beremiz writes them: sfc_action.xml (program Feeder's action Seq, an SFC) and
# sfc_fb.xml (function block TrafficLight, an SFC, called by program Crossing's ST body every
# scan) are read and checked without a word.
for name in sfc_action sfc_fb; do
  "$gfec" --check "$dir/$name.xml" 2> check.txt && [[ ! -s check.txt ]] || fail "$name.xml: --check: $(cat check.txt)"
done
# SFC inside an action and an SFC function block (docs/iec.md "SFC inside actions and function
# blocks"), "NAME:PROGRAM:TICKS": each runs with NAME.csv to NAME.expected (outputs; av lines
# aside), worked out by hand from docs/iec.md scan by scan; both engine forms print what the
# interpreter printed, and the converted chart text compiles to the same engine.
nested_sfc_cases=(sfc_action:Feeder:14 sfc_fb:Crossing:28)
for case in "${nested_sfc_cases[@]}"; do
  IFS=: read -r name pou ticks <<< "$case"
  "$gfec" run "$dir/$name.xml" --inputs "$dir/$name.csv" --observable --ticks "$ticks" > run.txt 2> run.err ||
    fail "$name.xml: gfec run fails: $(cat run.err)"
  grep -v '^av' run.txt | diff -u "$dir/$name.expected" - || fail "$name.xml: outputs differ from $name.expected"
  engines_agree "$name.xml" "$dir/$name.xml" "$dir/$name.csv" "$pou" "$ticks" run.txt
  rm -rf direct back && mkdir direct back
  "$gfec" --emit=chart "$dir/$name.xml" -o "back/$pou.sfc"
  "$gfec" "$dir/$name.xml" --no-line-directives -o direct/engine.c
  (cd back && "$gfec" "$pou.sfc" --no-line-directives -o engine.c)
  cmp <(tail -n +2 direct/engine.c) <(tail -n +2 back/engine.c) || fail "$name.xml: --emit=chart's text compiles to another engine"
done
# Global variables as Beremiz writes them (docs/iec.md "Global variables"): tests/iec/st/globals.st
# as PLCopen XML, located globalVars of the resource and a CONSTANT one of the configuration that
# the program declares in externalVars, reads without a word and runs to that program's log; both
# engine forms print it too, the located globals the engine's inputs and outputs.
"$gfec" --check "$dir/globals.xml" 2> globals.err && [[ ! -s globals.err ]] ||
  fail "globals.xml: --check: $(cat globals.err)"
"$gfec" run "$dir/globals.xml" --inputs "$dir/../st/globals.csv" --observable > globals.txt ||
  fail "globals.xml: gfec run fails"
diff -u "$dir/../st/globals.expected" globals.txt || fail "globals.xml runs to another log than tests/iec/st/globals.st"
engines_agree "globals.xml" "$dir/globals.xml" "$dir/../st/globals.csv" Station "" globals.txt

# A generated project: program Big of 500 steps and 23 more SFC programs, each holding an action
# whose body is an SFC, read, checked, compiled and built; their engines and the interpreter agree.
"$dir/gen_plcopen.sh" 500 24 > big.xml
"$gfec" --check big.xml || fail "big.xml: --check fails"
"$gfec" big.xml --chart Big -o big.c || fail "big.xml: Big does not compile"
cc -std=c99 -c big.c -o big.o || fail "big.xml: Big's engine does not build"
"$gfec" big.xml --chart Small23 -o small.c || fail "big.xml: Small23 does not compile"
# Without --chart, the program the task runs.
"$gfec" big.xml -o default.c || fail "big.xml: no default program"
grep -q 'void Big_run(Big \*' default.h || fail "big.xml: the default is not Big, the program task Main runs"
printf 'tick, Go, Skip\n1, 1, 0\n40, 1, 1\n41, 1, 0\n' > big.csv
"$gfec" run big.xml --inputs big.csv --observable --ticks 60 > big_run.txt
grep -q '^out Count = 1[0-9]$' big_run.txt || fail "big.xml: Big's Count does not count"
# Small23's step S1 holds Sub, an action whose body is an SFC: Tally (by two) runs inside it.
"$gfec" run big.xml --chart Small23 --inputs big.csv --observable --ticks 60 > small_run.txt
[[ $(grep -c '^out Count' small_run.txt) -eq 60 ]] && ! grep -q '^out Count = [0-9]$' <(tail -1 small_run.txt) ||
  fail "big.xml: Small23's Count does not count"
engines_agree "big.xml Small23" big.xml big.csv Small23 60 small_run.txt --chart Small23
# Big in structured text (gen_plcopen.sh --st, MatIEC's input in docs/performance.md (g)) is the
# program the XML says: the same log, activations included, over a trace round the whole loop.
"$dir/gen_plcopen.sh" 500 1 > big1.xml
"$dir/gen_plcopen.sh" --st 500 > Big.st
"$dir/gen_plcopen.sh" --trace > loop.csv
"$gfec" run big1.xml --inputs loop.csv --observable > xml_loop.txt
"$gfec" run Big.st --inputs loop.csv --observable > st_loop.txt
cmp -s xml_loop.txt st_loop.txt || fail "Big.st and big1.xml run differently: diff $(diff xml_loop.txt st_loop.txt | head -3)"
awk '$1 == "av" && NF == 501 && $NF == 1 { last = 1 } END { exit !last }' st_loop.txt ||
  fail "Big.st: the loop trace never reaches the last step S499"

# FBD and LD (networks.xml, docs/iec.md "FBD and LD bodies"): a program with an FBD body, one with
# an LD body and an SFC whose conditions are an LD rung and an FBD block run to the outputs worked
# out by hand; both engine forms print what the interpreter printed; the converted chart text
# compiles to the same engine.
for case in gates:Gates:4 latch:Latch:6 seq:Seq:7; do
  IFS=: read -r name pou ticks <<< "$case"
  "$gfec" run "$dir/networks.xml" --chart "$pou" --inputs "$dir/$name.csv" --observable --ticks "$ticks" > run.txt 2> run.err ||
    fail "networks.xml $pou: gfec run fails: $(cat run.err)"
  grep -v '^av' run.txt | diff -u "$dir/$name.expected" - || fail "networks.xml $pou: outputs differ from $name.expected"
  engines_agree "networks.xml $pou" "$dir/networks.xml" "$dir/$name.csv" "$pou" "$ticks" run.txt --chart "$pou"
  rm -rf direct back && mkdir direct back
  "$gfec" --emit=chart "$dir/networks.xml" --chart "$pou" -o "back/$pou.sfc"
  "$gfec" "$dir/networks.xml" --chart "$pou" --no-line-directives -o direct/engine.c
  (cd back && "$gfec" "$pou.sfc" --no-line-directives -o engine.c)
  cmp <(tail -n +2 direct/engine.c) <(tail -n +2 back/engine.c) ||
    fail "networks.xml $pou: --emit=chart's text compiles to another engine"
done

# Standard functions as FBD blocks (standard_fbd.xml: LIMIT, SEL, MAX): the outputs worked out by
# hand; both engine forms print what the interpreter printed.
"$gfec" run "$dir/standard_fbd.xml" --chart Clamp --inputs "$dir/standard_fbd.csv" --observable --ticks 4 > run.txt 2> run.err ||
  fail "standard_fbd.xml: gfec run fails: $(cat run.err)"
grep -v '^av' run.txt | diff -u "$dir/standard_fbd.expected" - || fail "standard_fbd.xml: outputs differ from standard_fbd.expected"
engines_agree "standard_fbd.xml" "$dir/standard_fbd.xml" "$dir/standard_fbd.csv" Clamp 4 run.txt --chart Clamp

# XML that is not PLCopen, as a PLC project's folder holds it (a Beremiz project's beremiz.xml, a
# Maven POM): one located error naming the root or the namespace, exit 1, never chart text's
# syntax errors.
printf '<?xml version="1.0" encoding="utf-8"?>\n<BeremizRoot URI_location="LOCAL://">\n  <TargetType/>\n</BeremizRoot>\n' > beremiz.xml
status=0
"$gfec" --check beremiz.xml 2> beremiz.err || status=$?
[ "$status" = 1 ] || fail "beremiz.xml: exit $status, not 1"
[ "$(grep -c 'error:' beremiz.err)" = 1 ] || fail "beremiz.xml: not one error: $(cat beremiz.err)"
grep -q '^beremiz.xml:2:1: error: the root element is <BeremizRoot>' beremiz.err || fail "beremiz.xml: $(cat beremiz.err)"
printf '<project xmlns="http://maven.apache.org/POM/4.0.0">\n</project>\n' > pom.xml
status=0
"$gfec" --check pom.xml 2> pom.err || status=$?
[ "$status" = 1 ] || fail "pom.xml: exit $status, not 1"
grep -q "^pom.xml:1:[0-9]*: error: the namespace 'http://maven.apache.org/POM/4.0.0' is not one gfec reads" pom.err ||
  fail "pom.xml: $(cat pom.err)"

# Truncations and garbage of every sample: exit 0 or 1 with located messages, never a crash, exit 2
# or a hang.
check_robust() {
  local rc=0
  timeout 10 "$gfec" --check "$1" > /dev/null 2> robust.err || rc=$?
  [[ $rc -le 1 ]] || fail "$2: exit $rc: $(head -c 600 robust.err)"
}
for producer in beremiz openplc codesys twincat tc6_old; do
  src=$dir/$producer.xml
  size=$(wc -c < "$src")
  for ((cut = 0; cut < size; cut += 401)); do
    head -c "$cut" "$src" > cut.xml
    check_robust cut.xml "$producer cut at byte $cut"
  done
  # Garbage: a byte overwritten with each of a few characters that matter to XML or to ST.
  for ((at = 150; at < size; at += 601)); do
    for c in "<" ">" "&" "(" "x"; do
      { head -c "$at" "$src"; printf '%s' "$c"; tail -c +"$((at + 2))" "$src"; } > bad.xml
      check_robust bad.xml "$producer with '$c' at byte $at"
    done
  done
done
# Links that meet again and again (each simultaneous convergence fed twice by the one before it,
# 60 deep), and a cycle of divergences: read in linear time, never walked path by path.
{
  echo '<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous><pou name="P" pouType="program"><body><SFC>'
  echo '<step localId="1" name="S0" initialStep="true"/>'
  echo '<simultaneousConvergence localId="100"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointIn><connection refLocalId="1"/></connectionPointIn></simultaneousConvergence>'
  for ((k = 101; k < 160; ++k)); do
    echo "<simultaneousConvergence localId=\"$k\"><connectionPointIn><connection refLocalId=\"$((k - 1))\"/></connectionPointIn><connectionPointIn><connection refLocalId=\"$((k - 1))\"/></connectionPointIn></simultaneousConvergence>"
  done
  echo '<transition localId="2"><connectionPointIn><connection refLocalId="159"/></connectionPointIn><condition><inline><ST>TRUE</ST></inline></condition></transition>'
  echo '<selectionDivergence localId="200"><connectionPointIn><connection refLocalId="201"/></connectionPointIn></selectionDivergence>'
  echo '<selectionDivergence localId="201"><connectionPointIn><connection refLocalId="200"/></connectionPointIn></selectionDivergence>'
  echo '<transition localId="3"><connectionPointIn><connection refLocalId="201"/></connectionPointIn><condition><inline><ST>TRUE</ST></inline></condition></transition>'
  echo '<jumpStep localId="4" targetName="S0"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></jumpStep>'
  echo '</SFC></body></pou></pous></types></project>'
} > diamonds.xml
check_robust diamonds.xml "diamonds.xml"

# An FBD network whose every block reads the one before it twice (60 deep): its text would double
# at each block; it is reported, fast, never written out.
{
  echo '<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous><pou name="P" pouType="program">'
  echo '<interface><outputVars><variable name="Q"><type><DINT/></type></variable></outputVars></interface><body><FBD>'
  echo '<inVariable localId="1"><expression>1</expression></inVariable>'
  prev=1
  for ((k = 2; k < 62; ++k)); do
    echo "<block localId=\"$k\" typeName=\"ADD\"><inputVariables><variable formalParameter=\"IN1\"><connectionPointIn><connection refLocalId=\"$prev\"/></connectionPointIn></variable><variable formalParameter=\"IN2\"><connectionPointIn><connection refLocalId=\"$prev\"/></connectionPointIn></variable></inputVariables></block>"
    prev=$k
  done
  echo "<outVariable localId=\"100\"><connectionPointIn><connection refLocalId=\"$prev\"/></connectionPointIn><expression>Q</expression></outVariable>"
  echo '</FBD></body></pou></pous></types></project>'
} > fanout.xml
rc=0
timeout 10 "$gfec" --check fanout.xml 2> fanout.err || rc=$?
[[ $rc == 1 ]] && grep -q 'more than gfec writes as one expression' fanout.err || fail "fanout.xml: exit $rc: $(head -c 300 fanout.err)"

# A UTF-16 file is PLCopen in an encoding gfec does not read: one located error, exit 1.
iconv -f UTF-8 -t UTF-16 "$dir/beremiz.xml" > utf16.xml
rc=0
"$gfec" --check utf16.xml 2> utf16.err || rc=$?
[[ $rc == 1 ]] && grep -q 'utf16.xml:1:1: error: the file is UTF-16' utf16.err || fail "UTF-16: exit $rc: $(head -c 300 utf16.err)"
echo "plcopen: ok"
