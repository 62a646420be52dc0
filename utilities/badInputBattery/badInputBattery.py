#!/usr/bin/python3
"""badInputBattery: runs generateParticles and wcsph on one small edit of a shipped case per
input, 100 and more of them in the classes of doc/reliability.md, and checks that each ends as
documented: a clear error (exit status 1, no signal, within the time limit, before the first
step, with the expected message) or, for the inputs marked so, a warning and a normal run.
Anything else is a finding: a crash (a signal, exit status 3), a hang, or silent acceptance.

    badInputBattery.py [--markdown FILE]

Binaries from $SPHKIT_BIN (default build/bin). --markdown writes the table doc/badInput.md
holds (the case directory in messages written <case>). Exit status 1 when any input fails.
Run by CTest as BadInputBattery, which also checks that doc/badInput.md is what it writes.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.path.abspath(os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin")))
GENERATE = "generateParticlesDict"


def edit(file, old, new):
    """An edit of a case file: the first `old` becomes `new` (the file is created if old is None)."""
    return ("edit", file, old, new)


def append(file, text):
    return ("append", file, text)


def state(file, pattern, replacement):
    """An edit of the XML header of a generated state file (0/fluid.vtu or 0/walls.vtu)."""
    return ("state", file, pattern, replacement)


def action(function):
    """Any change to the case directory, after generation."""
    return ("action", function)


# (class, what was changed, case, changes, expected part of the message, outcome).
# Outcome "error": exit status 1 before the first step; "warning": the expected text printed
# and a normal end; "refused": exit status 2 for a command-line option.
INPUTS = []


def add(kind, what, changes, expected, case="damBreak2D", outcome="error", tools=("generateParticles", "wcsph"), arguments=()):
    INPUTS.append(dict(kind=kind, what=what, changes=changes, expected=expected, case=case, outcome=outcome, tools=tools,
                       arguments=arguments))


SCHEMES, TIME, CONTROL, FLUID, BOUNDARY = ("system/sphSchemes", "system/timeIntegration", "system/controlDict",
                                           "constant/fluidProperties", "constant/boundaryProperties")
PARTICLES = "system/" + GENERATE

# Syntax.
add("syntax", "`courant 0.2` without `;`", [edit(TIME, "courant     0.2;", "courant     0.2")], "entry 'courant' is not terminated by ';'")
add("syntax", "a `{` never closed", [edit(SCHEMES, "kernel              { type wendlandC2; hdx 1.3; }", "kernel { type wendlandC2; hdx 1.3;")],
    "opened by '{' is never closed by '}'")
add("syntax", "a `}` with no `{`", [append(SCHEMES, "}\n")], "'}' has no matching '{'")
add("syntax", "a string not closed", [edit(CONTROL, "application     wcsph;", "application \"wcsph;")], "string is not closed by '\"' on the same line")
add("syntax", "a `/*` comment not closed", [append(SCHEMES, "/* a note\n")], "comment '/*' is never closed by '*/'")
add("syntax", "a `)` with no `(`", [edit(FLUID, "gravity     (0 -9.81);", "gravity     (0 -9.81));")], "')' has no matching '('")
add("syntax", "a list not closed", [edit(FLUID, "gravity     (0 -9.81);", "gravity     (0 -9.81;")], "inside the list opened at line")
add("syntax", "unknown directive `#includ`", [append(SCHEMES, "#includ \"other\"\n")],
    "unknown directive '#includ' (valid: #include, #includeParameters, and #eval in a value)")
add("syntax", "`#eval` of a malformed expression", [edit(FLUID, "rho0        1000;", "rho0        #eval \"1000 *\";")],
    "#eval \"1000 *\": Unexpected end of expression")
add("syntax", "`#eval` dividing by zero", [edit(FLUID, "rho0        1000;", "rho0        #eval \"1000 / 0\";")],
    "#eval \"1000 / 0\" is infinite (a division by zero?)")
add("syntax", "`#eval` over a macro naming a list", [edit(FLUID, "gravity     (0 -9.81);", "gravity     (0 -9.81);\ng2 #eval \"2 * $gravity\";")],
    "macro '$gravity' must name one number; it names 4 tokens")
add("syntax", "`#include` of a missing file", [append(SCHEMES, "#include \"missing\"\n")], "#include \"missing\": error: cannot open dictionary")
add("syntax", "`#include \"/dev/zero\"`", [append(SCHEMES, "#include \"/dev/zero\"\n")], "'/dev/zero': not a regular file")
add("syntax", "an `#include` that includes itself", [append(SCHEMES, "#include \"sphSchemes\"\n")], "#include nested more than 32 deep (an include cycle?)")
add("syntax", "`$undefined` macro", [edit(FLUID, "rho0        1000;", "rho0        $density;")], "macro '$density' refers to no entry defined before it")
add("syntax", "a dictionary nested 20,000 deep", [append(SCHEMES, "deep " + "{ a " * 20000 + "\n")], "dictionaries nested more than 100 deep")
add("syntax", "60 macros that each double the one before",
    [append(SCHEMES, "m0 (1 2);\n" + "".join("m%d ($m%d $m%d);\n" % (i, i - 1, i - 1) for i in range(1, 61)))],
    "the dictionary expands to more than 2000000 tokens")
add("syntax", "a 17 MiB dictionary", [append(SCHEMES, "// " + "x" * (17 << 20) + "\n")], "more than the 16 MiB a dictionary may have")
add("syntax", "`rho0 1e400`", [edit(FLUID, "rho0        1000;", "rho0        1e400;")], "number 1e400 is outside the range of a double")
add("syntax", "`rho0 1e-400`", [edit(FLUID, "rho0        1000;", "rho0        1e-400;")], "number 1e-400 is outside the range of a double")
add("syntax", "list size prefix that does not match", [edit(FLUID, "gravity     (0 -9.81);", "gravity     3(0 -9.81);")],
    "list size 3 does not match its 2 items")
add("syntax", "a keyword with no value", [edit(TIME, "courant     0.2;", "courant;")], "entry 'courant' has no value before ';'")

# Unknown names.
add("unknown name", "kernel `wendland`", [edit(SCHEMES, "type wendlandC2;", "type wendland;")], "unknown kernel 'wendland'; valid kernel names are:")
add("unknown name", "density `summaton`", [edit(SCHEMES, "type continuity;", "type summaton;")], "valid")
add("unknown name", "viscosity `artifical`", [edit(SCHEMES, "type artificial;", "type artifical;")], "valid")
add("unknown name", "density diffusion `fourtaka`", [edit(SCHEMES, "type fourtakas;", "type fourtaka;")], "valid")
add("unknown name", "particle shifting `sunn`", [append(SCHEMES, "particleShifting { type sunn; }\n")], "did you mean 'sun'")
add("unknown name", "integrator `symplectik`", [edit(TIME, "type symplectic;", "type symplectik;")], "valid")
add("unknown name", "equation of state `tate`", [edit(FLUID, "type            tait;", "type            tate;")], "valid")
add("unknown name", "boundary model `ghostParticles`", [edit(BOUNDARY, "dummyParticles", "ghostParticles")],
    "unknown boundary model 'ghostParticles'; valid boundary model names are:")
add("unknown name", "repulsion partner `springs`",
    [edit(BOUNDARY, "tank        { type dummyParticles; noSlip no; }", "tank { type deficiencyCorrection; repulsion { type springs; } }"),
     edit(PARTICLES, "layers 3;", "layers 1; firstLayerOffset 0;")], "springs")
add("unknown name", "calibration `wallPresure`",
    [edit(BOUNDARY, "tank        { type dummyParticles; noSlip no; }", "tank { type deficiencyCorrection; calibration wallPresure; }"),
     edit(PARTICLES, "layers 3;", "layers 1; firstLayerOffset 0;")], "wallPresure")
add("unknown name", "motion `wobble`", [edit(BOUNDARY, "noSlip no; }", "noSlip no; motion { type wobble; } }")], "wobble")
add("unknown name", "function object `surgeFrnt`", [edit(CONTROL, "type            surgeFront;", "type            surgeFrnt;")], "surgeFrnt")
add("unknown name", "wall patch type `cylinder`", [edit(PARTICLES, "type boxWalls;", "type cylinder;")], "unknown wall patch type 'cylinder'; valid wall patch type names are:")
add("unknown name", "fluid region type `sphere`", [edit(PARTICLES, "column  { type box;", "column  { type sphere;")],
    "unknown fluid region type 'sphere'; valid fluid region type names are:")
add("unknown name", "periodic direction `w`", [edit(PARTICLES, "max (0.43 0.2); }", "max (0.43 0.2); periodic (w); }")],
    "unknown direction 'w'; valid directions are: x y")
add("unknown name", "`startFrom firstTime`", [edit(CONTROL, "startFrom       latestTime;", "startFrom       firstTime;")],
    "expected latestTime or startTime, found 'firstTime'")
add("unknown name", "`outOfDomain delete`", [append(CONTROL, "outOfDomain delete;\n")], "expected stop or remove, found 'delete'")
add("unknown name", "misspelt keyword `courrant`", [edit(TIME, "courant     0.2;", "courrant     0.2;")], "'courrant' in dictionary 'timeIntegration'")
add("unknown name", "misspelt keyword in a model, `alfa`", [edit(SCHEMES, "alpha 0.02;", "alfa 0.02;")], "keyword 'alpha' is missing")
add("unknown name", "a patch that is not in the state", [append(BOUNDARY, "lid { type dummyParticles; }\n")],
    "patch 'lid' in constant/boundaryProperties is not a wall patch of the case; its patches are: tank")
add("unknown name", "`initialPressure hydrostatik`", [edit(PARTICLES, "initialPressure hydrostatic;", "initialPressure hydrostatik;")],
    "expected none, hydrostatic or analytic, found 'hydrostatik'")

# Missing keywords and files.
add("missing", "`endTime` absent", [edit(CONTROL, "endTime         0.2;", "")], "keyword 'endTime' is missing from dictionary 'controlDict'")
add("missing", "`writeInterval` absent", [edit(CONTROL, "writeInterval   0.01;", "")], "keyword 'writeInterval' is missing")
add("missing", "`rho0` absent", [edit(FLUID, "rho0        1000;", "")], "keyword 'rho0' is missing")
add("missing", "`equationOfState` absent", [edit(FLUID, "equationOfState", "eos")], "'equationOfState' is missing")
add("missing", "`kernel` absent", [edit(SCHEMES, "kernel              { type wendlandC2; hdx 1.3; }", "")], "keyword 'kernel' is missing")
add("missing", "`integrator` absent", [edit(TIME, "integrator  { type symplectic; }", "")], "keyword 'integrator' is missing")
add("missing", "`spacing` absent", [edit(PARTICLES, "spacing     0.0028575;", "")], "keyword 'spacing' is missing")
add("missing", "`dimension` absent", [edit(PARTICLES, "dimension   2;", "")], "keyword 'dimension' is missing")
add("missing", "`domain` absent", [edit(PARTICLES, "domain      { min (-0.03 -0.03); max (0.43 0.2); }", "")], "keyword 'domain' is missing")
add("missing", "`fluid` absent", [edit(PARTICLES, "fluid\n{", "liquid\n{")], "keyword 'fluid' is missing")
add("missing", "no model for a patch", [edit(BOUNDARY, "tank        { type dummyParticles; noSlip no; }", "")], "tank")
add("missing", "no speed of sound", [edit(FLUID, "c0FromHeight    { coefficient 10; height 0.1143; }   // 10 sqrt(g 2a)", "")], "c0")
add("missing", "`system/sphSchemes` deleted", [action(lambda d: os.remove(os.path.join(d, SCHEMES)))],
    "cannot open dictionary '<case>/system/sphSchemes': file not found", tools=("wcsph",))
add("missing", "no 0/ (generateParticles not run)", [], "run generateParticles first to write 0/", tools=("wcsph",))
add("missing", "`startTime` that was not written", [append(CONTROL, "startFrom startTime;\nstartTime 0.5;\n")],
    "no time directory 0.5 with a fluid.vtu or fluid.pvtu; written times are: 0")
add("missing", "the reference .csv of a function object deleted", [action(lambda d: os.remove(os.path.join(d, "martinMoyce1952Front.csv")))],
    "martinMoyce1952Front.csv", tools=("wcsph",))
add("missing", "0/walls.vtu deleted", [action(lambda d: os.remove(os.path.join(d, "0", "walls.vtu")))], "walls.vtu' does not exist", tools=("wcsph",))
add("missing", "a case directory that does not exist", [], "does not exist", tools=("wcsph",), arguments=("-case", "/nonexistent/case"))

# Wrong type.
add("wrong type", "`writeInterval often`", [edit(CONTROL, "writeInterval   0.01;", "writeInterval   often;")], "expected a number, found word 'often'")
add("wrong type", "`courant (0.2)`", [edit(TIME, "courant     0.2;", "courant     (0.2);")], "keyword 'courant' in dictionary 'timeIntegration': expected a number")
add("wrong type", "`hdx` a list", [edit(SCHEMES, "hdx 1.3;", "hdx (1.3);")], "keyword 'hdx'")
add("wrong type", "`noSlip maybe`", [edit(BOUNDARY, "noSlip no;", "noSlip maybe;")], "expected a switch (yes/no, true/false, on/off), found word 'maybe'")
add("wrong type", "`gravity` a number", [edit(FLUID, "gravity     (0 -9.81);", "gravity     -9.81;")], "keyword 'gravity'")
add("wrong type", "`gravity` with 3 components in 2D", [edit(FLUID, "gravity     (0 -9.81);", "gravity     (0 -9.81 0);")],
    "expected a vector of 2 components for a 2D case, found 3")
add("wrong type", "`layers 1.5`", [edit(PARTICLES, "layers 3;", "layers 1.5;")], "expected an integer, found number 1.5")
add("wrong type", "`dimension two`", [edit(PARTICLES, "dimension   2;", "dimension   two;")], "expected a number, found word 'two'")
add("wrong type", "`kernel wendlandC2` (a word for a dictionary)", [edit(SCHEMES, "kernel              { type wendlandC2; hdx 1.3; }", "kernel wendlandC2;")],
    "must be a dictionary { ... }, found the value 'wendlandC2'")
add("wrong type", "`layers 1e308`", [edit(PARTICLES, "layers 3;", "layers 1e308;")], "expected an integer, found number 1e308")

# Out of range.
add("out of range", "`spacing 0`", [edit(PARTICLES, "spacing     0.0028575;", "spacing     0;")], "must be greater than zero, found 0")
add("out of range", "`spacing -1`", [edit(PARTICLES, "spacing     0.0028575;", "spacing     -1;")], "must be greater than zero, found -1")
add("out of range", "`spacing 1e-10` (an int overflow on c09449c)", [edit(PARTICLES, "spacing     0.0028575;", "spacing     1e-10;")],
    "is the spacing a slip?")
add("out of range", "`spacing 2e-6` (2.6e10 lattice points)", [edit(PARTICLES, "spacing     0.0028575;", "spacing     2e-6;")],
    "GiB of memory; this machine has")
add("out of range", "`layers 0`", [edit(PARTICLES, "layers 3;", "layers 0;")], "must be from 1 to 1000, found 0")
add("out of range", "`layers 100000000`", [edit(PARTICLES, "layers 3;", "layers 100000000;")], "must be from 1 to 1000, found 100000000")
add("out of range", "`hdx 0.8`", [edit(SCHEMES, "hdx 1.3;", "hdx 0.8;")], "hdx 0.8")
add("out of range", "`courant 10`", [edit(TIME, "courant     0.2;", "courant     10;")], "must not exceed 1")
add("out of range", "`courant 0`", [edit(TIME, "courant     0.2;", "courant     0;")], "must be greater than zero, found 0")
add("out of range", "`rho0 -1000`", [edit(FLUID, "rho0        1000;", "rho0        -1000;")], "rho0")
add("out of range", "`endTime 0`", [edit(CONTROL, "endTime         0.2;", "endTime         0;")], "must be later than the start time 0, found 0")
add("out of range", "`writeInterval -1`", [edit(CONTROL, "writeInterval   0.01;", "writeInterval   -1;")], "writeInterval")
add("out of range", "`dimension 4`", [edit(PARTICLES, "dimension   2;", "dimension   4;")], "must be 1, 2 or 3, found 4")
add("out of range", "`alpha -1`", [edit(SCHEMES, "alpha 0.02;", "alpha -1;")], "alpha")
add("out of range", "`gamma 0`", [edit(FLUID, "gamma           7;", "gamma           0;")], "gamma")
add("out of range", "lineSample `points 2000000000`", [edit(CONTROL, "points               46;", "points               2000000000;")],
    "must be from 2 to 10000000, found 2000000000", case="hydrostaticTank2D")
add("out of range", "lineSample `points 1`", [edit(CONTROL, "points               46;", "points               1;")], "must be from 2 to 10000000, found 1",
    case="hydrostaticTank2D")
add("out of range", "`eulerEvery 0`", [edit(TIME, "type symplectic;", "type verlet; eulerEvery 0;")], "must be at least 1, found 0")
add("out of range", "`delta -0.1`", [edit(SCHEMES, "delta 0.1;", "delta -0.1;")], "delta")
add("out of range", "particle shifting `n 2.5`", [append(SCHEMES, "particleShifting { type sun; n 2.5; }\n")], "whole power, found 2.5")
add("out of range", "particle shifting `surfaceLambda 1.5`", [append(SCHEMES, "particleShifting { type lind; surfaceLambda 1.5; }\n")],
    "a threshold above it marks every particle as free surface")

# Inconsistent models.
add("inconsistent models", "density diffusion with summation density", [edit(SCHEMES, "type continuity;", "type summation;")], "diffusion")
add("inconsistent models", "particle shifting with `cvode`", [append(SCHEMES, "particleShifting { type sun; }\n"), edit(TIME, "type symplectic;", "type cvode;")],
    "particle shifting moves the particles after every step")
add("inconsistent models", "`velocityBlock` with artificial viscosity", [edit(TIME, "type symplectic;", "type arkodeIMEX; jacobianTimesVector velocityBlock;")],
    "velocityBlock is exact only for a viscosity linear in velocity (laminar)")
add("inconsistent models", "a free body with `verlet`", [edit(TIME, "type symplectic;", "type verlet;")],
    "only the symplectic integrator advances; found verlet", case="sinkingCylinder2D")
add("inconsistent models", "a wall-force model on 3 layers", [edit(BOUNDARY, "tank        { type dummyParticles; noSlip no; }", "tank { type deficiencyCorrection; }")],
    "acts from one layer of wall particles on the wall surface, but patch 'tank' has 3 layers")
add("inconsistent models", "dummy particles on one layer", [edit(PARTICLES, "layers 3;", "layers 1;")], "needs at least")
add("inconsistent models", "the correction's `noSlip yes` with artificial viscosity",
    [edit(BOUNDARY, "tank        { type dummyParticles; noSlip no; }", "tank { type deficiencyCorrectionBoundaryIntegral; noSlip yes; }"),
     edit(PARTICLES, "layers 3;", "layers 1; firstLayerOffset 0;")], "a no-slip wall on the correction needs viscosity laminar")
add("inconsistent models", "`sample` with the wallPressure calibration",
    [edit(BOUNDARY, "tank        { type dummyParticles; noSlip no; }", "tank { type deficiencyCorrection; sample 6; }"),
     edit(PARTICLES, "layers 3;", "layers 1; firstLayerOffset 0;")], "sample")
add("inconsistent models", "a motion table shorter than the run",
    [edit("motion.csv", None, "# t x y\n0 0 0\n0.001 0 0\n"),
     edit(BOUNDARY, "noSlip no; }", "noSlip no; motion { type table; file \"motion.csv\"; } }")], "covers t from 0 to 0.001, but the run goes from 0 to 0.004")

# Inconsistent geometry.
add("inconsistent geometry", "fluid outside the domain", [edit(PARTICLES, "max ($a 0.1143); }", "max ($a 0.2286); }")],
    "fluid region 'column' has a particle at")
add("inconsistent geometry", "a wall patch outside the domain", [edit(PARTICLES, "max (0.40005 0.17145); layers 3;", "max (0.8001 0.17145); layers 3;")],
    "outside the domain")
add("inconsistent geometry", "a box under half a spacing across", [edit(PARTICLES, "max ($a 0.1143); }", "max (0.001 0.1143); }")],
    "must be at least half a spacing")
add("inconsistent geometry", "a 2D surface region whose file is missing", [edit(PARTICLES, "column  { type box; min (0 0); max ($a 0.1143); }",
                                                                                 "column  { type surface; file \"column.obj\"; }")],
    "surface file '<case>/column.obj' does not exist")
add("inconsistent geometry", "a fluid region inside the wall", [edit(PARTICLES, "column  { type box; min (0 0); max ($a 0.1143); }",
                                                                       "column  { type box; min (-0.0057150 0); max (0 0.1143); }")],
    "holds no particle")
add("inconsistent geometry", "domain max below min", [edit(PARTICLES, "max (0.43 0.2); }", "max (0.43 -0.2); }")], "must exceed min in every direction")
add("inconsistent geometry", "a wall patch listed twice", [edit(PARTICLES, "open (yMax); }", "open (yMax); }\n    again { type boxWalls; min (0 0); max (0.40005 0.17145); layers 3; open (yMax); }")],
    "wall patch 'again' lays 798 of its 798 particles on those of patch 'tank' (the same patch listed twice?)")
add("inconsistent geometry", "a polygon of 2 points", [edit(PARTICLES, "column  { type box; min (0 0); max ($a 0.1143); }", "column { type polygon; points ((0 0) (0.05 0)); }")],
    "a polygon needs at least 3 points")
add("inconsistent geometry", "a polyline tank's `side` the wrong way round",
    [edit(PARTICLES, "tank    { type boxWalls; min (0 0); max (0.40005 0.17145); layers 3; open (yMax); }",
          "tank    { type polyline; points ((0 0.17145) (0 0) (0.40005 0) (0.40005 0.17145)); side right; layers 3; }")],
    "wall patch 'tank' faces away from its fluid")
add("inconsistent geometry", "a polyline baffle drawn through the fluid (one-sided)",
    [edit(PARTICLES, "open (yMax); }", "open (yMax); }\n    baffle { type polyline; points ((0.03 0) (0.03 0.08)); layers 3; }"),
     edit(BOUNDARY, "tank        { type dummyParticles; noSlip no; }", "tank { type dummyParticles; noSlip no; }\nbaffle { type dummyParticles; }")],
    "wall patch 'baffle' has fluid on both sides")
add("inconsistent geometry", "fluid beside the tank (a warning)",
    [edit(PARTICLES, "column  { type box; min (0 0); max ($a 0.1143); }",
          "column  { type box; min (0 0); max ($a 0.1143); }\n    spill { type box; min (0.41 0); max (0.4242875 0.0142875); }")],
    "warning: fluid region 'spill' has 25 of its 25 particles outside the box around the wall particles", outcome="warning")

# Corrupt state files (the header of 0/fluid.vtu or 0/walls.vtu edited after generation).
FLUIDVTU, WALLSVTU = "0/fluid.vtu", "0/walls.vtu"
add("corrupt state file", "`NumberOfPoints=\"-5\"`", [state(FLUIDVTU, r'NumberOfPoints="\d+"', 'NumberOfPoints="-5"')],
    'NumberOfPoints="-5" in <Piece> is not a whole number >= 0', tools=("wcsph",))
add("corrupt state file", "`NumberOfPoints` ten times the data", [state(FLUIDVTU, r'NumberOfPoints="(\d+)"', lambda m: 'NumberOfPoints="%d0"' % int(m.group(1)))],
    "but the header implies", tools=("wcsph",))
add("corrupt state file", "`NumberOfCells` one more", [state(FLUIDVTU, r'NumberOfCells="(\d+)"', lambda m: 'NumberOfCells="%d"' % (int(m.group(1)) + 1))],
    "array 'connectivity'", tools=("wcsph",))
add("corrupt state file", "the Points array's offset one byte on", [state(FLUIDVTU, r'(Name="Points"[^>]*offset=")(\d+)', lambda m: m.group(1) + str(int(m.group(2)) + 1))],
    "array 'Points'", tools=("wcsph",))
add("corrupt state file", "an offset past the end of the file", [state(FLUIDVTU, r'(Name="density"[^>]*offset=")(\d+)', lambda m: m.group(1) + "99999999")],
    "starts past the end of the file", tools=("wcsph",))
add("corrupt state file", "`format=\"ascii\"`", [state(FLUIDVTU, r'format="appended"', 'format="ascii"')], 'has format="ascii"', tools=("wcsph",))
add("corrupt state file", "`byte_order=\"BigEndian\"`", [state(FLUIDVTU, "LittleEndian", "BigEndian")], "valid: LittleEndian", tools=("wcsph",))
add("corrupt state file", "`header_type=\"UInt16\"`", [state(FLUIDVTU, r'header_type="UInt\d+"', 'header_type="UInt16"')], "valid: UInt32, UInt64",
    tools=("wcsph",))
add("corrupt state file", "an LZ4 compressor", [state(FLUIDVTU, "vtkZLibDataCompressor", "vtkLZ4DataCompressor")], "valid: vtkZLibDataCompressor",
    tools=("wcsph",))
add("corrupt state file", "`type=\"Float65\"`", [state(FLUIDVTU, 'type="Float64"', 'type="Float65"')], 'has type "Float65"', tools=("wcsph",))
add("corrupt state file", "`NumberOfComponents=\"0\"`", [state(FLUIDVTU, 'NumberOfComponents="3"', 'NumberOfComponents="0"')], "valid: 1 to 1024",
    tools=("wcsph",))
add("corrupt state file", "an element `<DataArrayy>`", [state(FLUIDVTU, "<DataArray", "<DataArrayy")], "has the XML element <DataArrayy>", tools=("wcsph",))
add("corrupt state file", "a string array with fewer tuples", [state(WALLSVTU, r'(Name="patchNames" NumberOfTuples=")1', r'\g<1>2')],
    "strings, but NumberOfTuples says 2", tools=("wcsph",))
add("corrupt state file", "a PolyData file as a state", [state(FLUIDVTU, 'type="UnstructuredGrid"', 'type="PolyData"')], "is not a VTK XML UnstructuredGrid",
    tools=("wcsph",))
add("corrupt state file", "base64 appended data", [state(FLUIDVTU, 'encoding="raw"', 'encoding="base64"')], "appended data is not raw", tools=("wcsph",))
add("corrupt state file", "a letter before the data's `_`", [state(FLUIDVTU, r'(encoding="raw">\s*)_', r'\g<1>z_')], "is not followed by '_'", tools=("wcsph",))
add("corrupt state file", "fluid.vtu cut to half", [action(lambda d: truncate(os.path.join(d, FLUIDVTU), 0.5))], "run past the end of the file",
    tools=("wcsph",))
add("corrupt state file", "fluid.vtu empty", [action(lambda d: truncate(os.path.join(d, FLUIDVTU), 0.0))], "has no <AppendedData> section", tools=("wcsph",))
add("corrupt state file", "fluid.vtu a directory", [action(lambda d: (os.remove(os.path.join(d, FLUIDVTU)), os.mkdir(os.path.join(d, FLUIDVTU))))],
    "fluid.vtu' is not a regular file", tools=("wcsph",))
add("corrupt state file", "a text file as fluid.vtu", [action(lambda d: write(os.path.join(d, FLUIDVTU), "particles: 800\n"))],
    "has no <AppendedData> section", tools=("wcsph",))

# Overwrite and leftovers.
add("overwrite", "generateParticles on an existing 0/", [action(lambda d: None)], "exists; remove it (./Allclean) or pass -overwrite",
    tools=("generateParticles",))
add("overwrite", "`startFrom startTime` before later times", [action(lambda d: shutil.copytree(os.path.join(d, "0"), os.path.join(d, "0.01"))),
                                                              append(CONTROL, "startFrom startTime;\nstartTime 0;\n")],
    "the run would overwrite them", tools=("wcsph",))
add("overwrite", "a time directory without fluid.vtu (a warning)", [action(lambda d: os.mkdir(os.path.join(d, "0.5")))],
    "warning: skipping the time directory <case>/0.5: it holds no fluid.vtu", tools=("wcsph",), outcome="warning")

# Command line.
add("command line", "`wcsph -bogus`", [], "unknown or incomplete option '-bogus'", tools=("wcsph",), arguments=("-bogus",), outcome="refused")
add("command line", "`wcsph -case` without a directory", [], "unknown or incomplete option '-case'", tools=("wcsph",), arguments=("-case",),
    outcome="refused")
add("command line", "`wcsph -listModels kernels`", [], "unknown model family 'kernels'; valid: kernel density", tools=("wcsph",),
    arguments=("-listModels", "kernels"), outcome="refused")
add("command line", "`wcsph -threads 0`", [], "-threads takes a whole number from 1 to 4096, found '0'", tools=("wcsph",),
    arguments=("-threads", "0"), outcome="refused")
add("command line", "`wcsph -threads two`", [], "-threads takes a whole number from 1 to 4096, found 'two'", tools=("wcsph",),
    arguments=("-threads", "two"), outcome="refused")
add("command line", "`wcsph -parallel -balance 0.9`", [], "-balance takes 0 (keep the first partition) or a ratio of at least 1, found '0.9'",
    tools=("wcsph",), arguments=("-parallel", "-balance", "0.9"), outcome="refused")
add("command line", "`wcsph -balance 1.2` without -parallel", [], "-balance applies to a run on several ranks (wcsph -parallel under mpirun)",
    tools=("wcsph",), arguments=("-balance", "1.2"), outcome="refused")
add("command line", "`generateParticles -force`", [], "unknown or incomplete option '-force'", tools=("generateParticles",), arguments=("-force",),
    outcome="refused")


def truncate(path, fraction):
    with open(path, "r+b") as f:
        f.truncate(int(os.path.getsize(path) * fraction))


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def prepare(work, entry):
    """A copy of the entry's case at a coarse spacing and a short endTime (a silently accepted
    input then ends in seconds), with the entry's changes."""
    case = os.path.join(work, "case")
    shutil.rmtree(case, ignore_errors=True)
    source = os.path.join(ROOT, "cases", entry["case"])
    shutil.copytree(source, case, ignore=shutil.ignore_patterns("[0-9]*", "postProcessing", "variants", "log.*", "*.png"))
    coarse = {"damBreak2D": (PARTICLES, "spacing     0.00142875;", "spacing     0.0028575;"), "hydrostaticTank2D": None,
              "sinkingCylinder2D": ("system/caseParameters", "dx          0.01;", "dx          0.02;")}[entry["case"]]
    if coarse:
        text = open(os.path.join(case, coarse[0])).read()
        assert coarse[1] in text, (entry["case"], coarse)
        write(os.path.join(case, coarse[0]), text.replace(coarse[1], coarse[2], 1))
    control = os.path.join(case, CONTROL)
    endTime = re.search(r"\nendTime\s+[^;]+;", open(control).read()).group(0)
    generated = False
    for change in entry["changes"]:
        if change[0] in ("state", "action") and not generated:
            subprocess.run([os.path.join(BIN, "generateParticles"), "-case", case], check=True, capture_output=True)
            generated = True
        if change[0] == "edit":
            _, file, old, new = change
            path = os.path.join(case, file)
            if old is None:
                write(path, new)
            else:
                text = open(path).read()
                assert old in text, "%s: '%s' not in %s" % (entry["what"], old, file)
                write(path, text.replace(old, new, 1))
        elif change[0] == "append":
            with open(os.path.join(case, change[1]), "a") as f:
                f.write(change[2])
        elif change[0] == "state":
            _, file, pattern, replacement = change
            path = os.path.join(case, file)
            data = open(path, "rb").read()
            split = data.index(b"<AppendedData")
            header = data[:split + 40].decode("latin-1")
            edited, count = re.subn(pattern, replacement, header, count=1)
            assert count == 1, "%s: no '%s' in %s" % (entry["what"], pattern, file)
            open(path, "wb").write(edited.encode("latin-1") + data[split + 40:])
        else:
            change[1](case)
    # The case's own endTime (untouched by the entry) made short.
    write(control, open(control).read().replace(endTime, "\nendTime 0.004;", 1))
    if "generateParticles" not in entry["tools"] and not generated and entry["expected"] != "run generateParticles first to write 0/":
        subprocess.run([os.path.join(BIN, "generateParticles"), "-case", case], check=True, capture_output=True)
    return case


def run(entry, work):
    """(outcome, message): outcome "ok" when the input ended as documented, else what it did."""
    case = prepare(work, entry)
    output = ""
    for tool in entry["tools"]:
        arguments = list(entry["arguments"]) if entry["arguments"] else ["-case", case]
        try:
            done = subprocess.run([os.path.join(BIN, tool)] + arguments, capture_output=True, text=True, timeout=60,
                                  env=dict(os.environ, OMP_NUM_THREADS="1"))
        except subprocess.TimeoutExpired:
            return "hang", "%s ran past 60 s" % tool
        output += re.sub(r"this machine has [0-9.]+ GiB", "this machine has <n> GiB", (done.stdout + done.stderr).replace(case, "<case>"))
        if done.returncode < 0:
            return "crash", "%s: signal %d" % (tool, -done.returncode)
        if done.returncode not in (0, 1, 2):
            return "crash", "%s: exit status %d: %s" % (tool, done.returncode, output.strip().splitlines()[-1:])
        if done.returncode != 0:
            break
    message = next((line.strip() for line in output.splitlines() if entry["expected"] in line), "")
    if entry["outcome"] == "warning":
        return ("ok" if done.returncode == 0 and message else "missing warning"), message
    if done.returncode == 0:
        return "silent", "accepted"
    if not message:
        return "vague", output.strip().splitlines()[-1] if output.strip() else ""
    if entry["outcome"] == "error" and (done.returncode != 1 or "Starting time loop" in output):
        return "late", message
    if entry["outcome"] == "refused" and done.returncode != 2:
        return "wrong status", message
    return "ok", message


def markdown(rows):
    lines = ["# Bad input: every input of the battery and its message", "",
             "Written by `utilities/badInputBattery/badInputBattery.py --markdown doc/badInput.md`; CTest's",
             "BadInputBattery runs every row and checks this file is what the battery writes. Each input is",
             "one edit of a shipped case (damBreak2D at dx = a/20 unless named); the message is the line",
             "that holds the expected text, the case directory written `<case>` (and the memory free `<n>`). Outcome: *error* (exit",
             "status 1 before the first step), *warning* (printed, the run goes on), *refused* (a",
             "command-line option, exit status 2).", "",
             "| # | class | input | outcome | message |", "|---|---|---|---|---|"]
    for number, (entry, outcome, message) in enumerate(rows, 1):
        shown = message.replace("|", "\\|")
        if len(shown) > 300:
            shown = shown[:297] + "..."
        lines.append("| %d | %s | %s%s | %s | `%s` |" % (number, entry["kind"], entry["what"].replace("|", "\\|"),
                                                       "" if entry["case"] == "damBreak2D" else " (%s)" % entry["case"],
                                                       entry["outcome"] if outcome == "ok" else "**%s**" % outcome, shown.replace("`", "'")))
    failures = sum(1 for _, outcome, _ in rows if outcome != "ok")
    lines += ["", "%d inputs: %d as documented, %d findings." % (len(rows), len(rows) - failures, failures), ""]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--markdown", help="write the table to this file")
    parser.add_argument("--check", help="exit 1 unless this file holds the table the run writes")
    options = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for entry in INPUTS:
            outcome, message = run(entry, work)
            rows.append((entry, outcome, message))
            if outcome != "ok":
                print("FINDING %s: %s -> %s: %s" % (entry["kind"], entry["what"], outcome, message))
    table = markdown(rows)
    if options.markdown:
        write(options.markdown, table)
    failures = sum(1 for _, outcome, _ in rows if outcome != "ok")
    print("%d inputs: %d as documented, %d findings" % (len(rows), len(rows) - failures, failures))
    if options.check and open(options.check).read() != table:
        print("%s differs from what the battery writes: regenerate it with --markdown" % options.check)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
