#!/usr/bin/env bash
# Writes a large PLCopen TC6 XML project to stdout, for cli.plcopen and scripts/bench.sh: program
# Big with STEPS steps in a loop, and POUS-1 programs Small1... of 20 steps each, whose step S1
# holds action Sub, an SFC of three steps. Every tenth step
# opens a selection divergence (go on, or skip a step) that a selection convergence closes, every
# fifth holds action Count with N; task Main runs Big every 10 ms. Positions are all 0,0, as
# CODESYS writes them: only localId/refLocalId link the elements.
#   gen_plcopen.sh [STEPS [POUS]]      (default 500 steps, 24 programs)
# The same program Big in IEC structured text, for readers that take no XML (MatIEC: the
# comparison of docs/performance.md (g)), and an input trace that walks it round its loop:
#   gen_plcopen.sh --st [STEPS]        program Big alone, run by task Main every 10 ms; the
#                                      resource and instance are res and inst, the names
#                                      tests/iec/matiec/measure_matiec.py drives
#   gen_plcopen.sh --trace [ROWS]      columns Go, Skip (default 1000 rows: once round the loop
#                                      of 500 steps): Go falls every seventh scan, Skip is set
#                                      every third
set -euo pipefail
case ${1:-} in
  --st)
    awk -v n="${2:-500}" '
    BEGIN {
      print "PROGRAM Big"
      print "  VAR_INPUT"
      print "    Go : BOOL;"
      print "    Skip : BOOL;"
      print "  END_VAR"
      print "  VAR_OUTPUT"
      print "    Count : DINT := 0;"
      print "  END_VAR"
      for (i = 0; i < n; i++)
        print "  " (i == 0 ? "INITIAL_STEP" : "STEP") " S" i " :" (i % 5 == 0 ? " Inc(N);" : "") " END_STEP"
      # In the order of the XML: a step'"'"'s own transition, then the skip of its divergence.
      for (i = 0; i < n; i++) {
        print "  TRANSITION FROM S" i " TO S" (i + 1 < n ? i + 1 : 0) " := Go AND NOT Skip; END_TRANSITION"
        if (i % 10 == 0 && i + 2 < n) print "  TRANSITION FROM S" i " TO S" i + 2 " := Go AND Skip; END_TRANSITION"
      }
      print "  ACTION Inc:"
      print "    Count := Count + 1;"
      print "  END_ACTION"
      print "END_PROGRAM"
      print ""
      print "CONFIGURATION Plant"
      print "  RESOURCE res ON PLC"
      print "    TASK Main(INTERVAL := T#10ms, PRIORITY := 1);"
      print "    PROGRAM inst WITH Main : Big;"
      print "  END_RESOURCE"
      print "END_CONFIGURATION"
    }'
    exit 0 ;;
  --trace)
    awk -v rows="${2:-1000}" 'BEGIN { print "Go,Skip"; for (r = 0; r < rows; r++) print (r % 7 != 6) "," (r % 3 == 0) }'
    exit 0 ;;
esac
steps=${1:-500}
pous=${2:-24}
awk -v steps="$steps" -v pous="$pous" '
# An action whose body is an SFC (docs/iec.md "SFC inside actions and function blocks"): Sub, whose
# steps U0, U1, U2 go round on Go and NOT Skip; U1 holds Tally, which counts by two.
function sub_action() {
  print "          <action name=\"Tally\"><body><ST><xhtml:p><![CDATA[Count := Count + 2;]]></xhtml:p></ST></body></action>"
  print "          <action name=\"Sub\"><body><SFC>"
  print "            <step localId=\"1\" name=\"U0\" initialStep=\"true\"><position x=\"0\" y=\"0\"/><connectionPointOut formalParameter=\"\"/></step>"
  print "            <transition localId=\"2\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"1\"/></connectionPointIn>"
  print "              <condition><inline name=\"\"><ST><xhtml:p><![CDATA[Go]]></xhtml:p></ST></inline></condition></transition>"
  print "            <step localId=\"3\" name=\"U1\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"2\"/></connectionPointIn><connectionPointOut formalParameter=\"\"/></step>"
  print "            <actionBlock localId=\"4\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"3\"/></connectionPointIn>"
  print "              <action localId=\"0\" qualifier=\"N\"><relPosition x=\"0\" y=\"0\"/><reference name=\"Tally\"/></action></actionBlock>"
  print "            <transition localId=\"5\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"3\"/></connectionPointIn>"
  print "              <condition><inline name=\"\"><ST><xhtml:p><![CDATA[NOT Skip]]></xhtml:p></ST></inline></condition></transition>"
  print "            <step localId=\"6\" name=\"U2\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"5\"/></connectionPointIn><connectionPointOut formalParameter=\"\"/></step>"
  print "            <transition localId=\"7\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"6\"/></connectionPointIn>"
  print "              <condition><inline name=\"\"><ST><xhtml:p><![CDATA[Go]]></xhtml:p></ST></inline></condition></transition>"
  print "            <jumpStep localId=\"8\" targetName=\"U0\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"7\"/></connectionPointIn></jumpStep>"
  print "          </SFC></body></action>"
}
function pou(name, n, nested,    i, id, prev, t, d, c) {
  print "      <pou name=\"" name "\" pouType=\"program\">"
  print "        <interface>"
  print "          <inputVars><variable name=\"Go\"><type><BOOL/></type></variable>"
  print "            <variable name=\"Skip\"><type><BOOL/></type></variable></inputVars>"
  print "          <outputVars><variable name=\"Count\"><type><DINT/></type><initialValue><simpleValue value=\"0\"/></initialValue></variable></outputVars>"
  print "        </interface>"
  print "        <actions><action name=\"Inc\"><body><ST><xhtml:p><![CDATA[Count := Count + 1;]]></xhtml:p></ST></body></action>"
  if (nested) sub_action()
  print "        </actions>"
  print "        <body>"
  print "          <SFC>"
  # ids: step i is 10*i+1, its outgoing transition 10*i+2, divergence 10*i+3, skip transition
  # 10*i+4, convergence before step i 10*i+5, action block 10*i+6, jump back 10*i+7.
  for (i = 0; i < n; i++) {
    id = 10 * i + 1
    if (i == 0) prev = ""
    else if (i % 10 == 2 && i >= 2) prev = 10 * i + 5
    else prev = 10 * (i - 1) + 2
    print "            <step localId=\"" id "\" name=\"S" i "\"" (i == 0 ? " initialStep=\"true\"" : "") ">"
    print "              <position x=\"0\" y=\"0\"/>"
    if (prev != "") print "              <connectionPointIn><connection refLocalId=\"" prev "\"/></connectionPointIn>"
    print "              <connectionPointOut formalParameter=\"\"/>"
    print "            </step>"
    if (i % 5 == 0) {
      print "            <actionBlock localId=\"" 10 * i + 6 "\"><position x=\"0\" y=\"0\"/>"
      print "              <connectionPointIn><connection refLocalId=\"" id "\"/></connectionPointIn>"
      print "              <action localId=\"0\" qualifier=\"N\"><relPosition x=\"0\" y=\"0\"/><reference name=\"Inc\"/></action>"
      print "            </actionBlock>"
    }
    if (nested && i == 1) {
      print "            <actionBlock localId=\"" 10 * i + 6 "\"><position x=\"0\" y=\"0\"/>"
      print "              <connectionPointIn><connection refLocalId=\"" id "\"/></connectionPointIn>"
      print "              <action localId=\"0\" qualifier=\"N\"><relPosition x=\"0\" y=\"0\"/><reference name=\"Sub\"/></action>"
      print "            </actionBlock>"
    }
    from = id
    if (i % 10 == 0 && i + 2 < n) {
      d = 10 * i + 3
      print "            <selectionDivergence localId=\"" d "\"><position x=\"0\" y=\"0\"/>"
      print "              <connectionPointIn><connection refLocalId=\"" id "\"/></connectionPointIn>"
      print "            </selectionDivergence>"
      from = d
    }
    t = 10 * i + 2
    print "            <transition localId=\"" t "\"><position x=\"0\" y=\"0\"/>"
    print "              <connectionPointIn><connection refLocalId=\"" from "\"/></connectionPointIn>"
    print "              <condition><inline name=\"\"><ST><xhtml:p><![CDATA[Go AND NOT Skip]]></xhtml:p></ST></inline></condition>"
    print "            </transition>"
    if (i % 10 == 0 && i + 2 < n) {
      print "            <transition localId=\"" 10 * i + 4 "\"><position x=\"0\" y=\"0\"/>"
      print "              <connectionPointIn><connection refLocalId=\"" d "\"/></connectionPointIn>"
      print "              <condition><inline name=\"\"><ST><xhtml:p><![CDATA[Go AND Skip]]></xhtml:p></ST></inline></condition>"
      print "            </transition>"
      c = 10 * (i + 2) + 5
      print "            <selectionConvergence localId=\"" c "\"><position x=\"0\" y=\"0\"/>"
      print "              <connectionPointIn><connection refLocalId=\"" 10 * (i + 1) + 2 "\"/></connectionPointIn>"
      print "              <connectionPointIn><connection refLocalId=\"" 10 * i + 4 "\"/></connectionPointIn>"
      print "            </selectionConvergence>"
    }
  }
  print "            <jumpStep localId=\"" 10 * (n - 1) + 7 "\" targetName=\"S0\"><position x=\"0\" y=\"0\"/>"
  print "              <connectionPointIn><connection refLocalId=\"" 10 * (n - 1) + 2 "\"/></connectionPointIn>"
  print "            </jumpStep>"
  print "          </SFC>"
  print "        </body>"
  print "      </pou>"
}
BEGIN {
  print "<?xml version=\"1.0\" encoding=\"utf-8\"?>"
  print "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\" xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">"
  print "  <fileHeader companyName=\"gfec\" productName=\"gen_plcopen.sh\" productVersion=\"1\" creationDateTime=\"2026-12-07T00:00:00\"/>"
  print "  <types>"
  print "    <pous>"
  pou("Big", steps, 0)
  for (p = 1; p < pous; p++) pou("Small" p, 20, 1)
  print "    </pous>"
  print "  </types>"
  print "  <instances><configurations><configuration name=\"Plant\"><resource name=\"Cpu\">"
  print "    <task name=\"Main\" interval=\"T#10ms\" priority=\"1\"><pouInstance name=\"big\" typeName=\"Big\"/></task>"
  print "  </resource></configuration></configurations></instances>"
  print "</project>"
}'
