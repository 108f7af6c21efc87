#!/usr/bin/env python3
"""Audit of issue 4 ("What to build"): every key of the solid material library against
what the executable registers (`tephra --list FAMILY`), which model source reads each
option, and which test files name each key.

    python3 tests/bench/audit_solid_keys.py [--tephra build/bin/tephra] [--write]

Prints a markdown table (family | key | registered | read by | tests | state). With
--write it replaces the block between the markers
    <!-- audit_solid_keys:begin --> ... <!-- audit_solid_keys:end -->
in docs/models/README.md. Exit status 1 when a key is not registered (or, for an
option, read by no model source) or when no test names it: the gaps of the audit.

How a test "names" a key (tests/{unit,contract,verification}/*.cpp):
  constitutive_model      the quoted key ("key" or \\"key\\") appears in the file;
  sub-model families      the quoted key appears in a file that also names the family
                          (so "linear" of an interpolator test does not count for
                          flow_model);
  options                 the quoted key or the element <key> appears in the file.
The state column is derived, not written by hand: "registered, tested", "NOT
REGISTERED", "NO TEST", "READ BY NO MODEL". Whether a test checks the key against a
closed form is in docs/FEATURES.md (the row of the feature); this audit only finds
keys that nothing registers or nothing exercises.
"""
import argparse
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
README = ROOT / "docs" / "models" / "README.md"
BEGIN, END = "<!-- audit_solid_keys:begin -->", "<!-- audit_solid_keys:end -->"

# Issue 4, "What to build", items 1 and 2 (keys exactly as the issue and Vaango's schema spell them,
# with the older deck spellings the issue names as aliases).
FAMILIES = {
    "constitutive_model": [
        "elastic_plastic_hp", "elastic_plastic", "hypo_elastic", "polar_orthotropic_hypoelastic",
        "comp_neo_hook_plastic", "cnh_damage", "cnhp_damage", "UCNH", "trans_iso_hyper",
        "visco_trans_iso_hyper", "mw_visco_elastic", "visco_scram", "visco_plastic", "p_alpha",
        "hypo_elastic_mms", "cnh_mms", "ideal_gas", "water", "murnaghanMPM", "jwlpp_mpm",
        "program_burn", "tabular_eos"],
    "equation_of_state": ["default_hypo", "default_hyper", "mie_gruneisen", "mie_gruneisen_energy", "air",
                          "water", "granite"],
    "shear_modulus_model": ["constant_shear", "mts_shear", "scg_shear", "np_shear", "ptw_shear"],
    "yield_condition": ["von_mises", "vonMises", "gurson", "rousselier"],
    "flow_model": ["linear", "isotropic_hardening", "johnson_cook", "mechanical_threshold_stress", "mts_model",
                   "preston_tonks_wallace", "steinberg_cochran_guinan", "zerilli_armstrong",
                   "zerilli_armstrong_polymer"],
    "viscoplastic_flow_model": ["suvic_i"],
    "internal_variable_model": ["metal_internal_var"],
    "kinematic_hardening_model": ["prager", "armstrong_frederick"],
    "damage_model": ["johnson_cook", "hancock_mackenzie"],
    "melting_temp_model": ["constant_Tm", "linear_Tm", "scg_Tm", "bps_Tm"],
    "specific_heat_model": ["constant_Cp", "cubic_Cp", "copper_Cp", "steel_Cp"],
    "stability_check": ["none", "drucker", "acoustic", "becker", "drucker_becker"],
}
# Options of item 1 (and the porosity/damage/failure keys they switch on). Read by a model's
# create() through params.get_*("key"); an option no source reads would be a DeckError
# (unknown parameter) in a deck, one read and not used would be silently ignored: the
# "read by" column names the file to look at.
OPTIONS = [
    "isothermal", "tolerance", "do_melting", "taylor_quinney_coeff", "coeff_thermal_expansion",
    "evolve_porosity", "evolve_damage", "check_TEPLA_failure_criterion", "check_max_stress_failure",
    "critical_porosity", "critical_stress", "frac_nucleation", "meanstrain_nucleation",
    "stddevstrain_nucleation", "initial_porosity_distrib", "initial_mean_porosity", "initial_std_porosity",
    "initial_scalar_damage_distrib", "initial_mean_scalar_damage", "initial_std_scalar_damage",
    "useModifiedEOS", "plastic_convergence_algo", "compute_specific_heat",
    # visco_plastic (SUVIC-I) failure options (Vaango ViscoPlastic)
    "check_failure", "failure_variable_mean", "failure_variable_std", "failure_variable_distrib",
    "failure_by_stress", "failure_by_pressure", "zero_stress_upon_failure", "allow_no_tension",
    "remove_particles",
    # visco_plastic model options read and checked with no effect in Vaango's SUVIC-I (session 17)
    "initial_material_temperature", "use_polar_decomposition_RMB",
]


def listed(tephra, family):
    try:
        out = subprocess.run([tephra, "--list", family], capture_output=True, text=True, check=False)
    except FileNotFoundError:
        sys.exit(f"no executable {tephra}: build first (cmake --build build)")
    if out.returncode != 0:
        return None  # the family itself is unknown to --list
    return set(out.stdout.split())


def test_files():
    files = {}
    for tier in ("unit", "contract", "verification"):
        for f in sorted((ROOT / "tests" / tier).glob("test_*.cpp")):
            files[f.stem] = f.read_text(errors="replace")
    return files


def quoted(key):
    return re.compile(r'(?:"|\\")' + re.escape(key) + r'(?:"|\\")')


def tests_naming(files, family, key):
    pat = quoted(key)
    element = re.compile(r"<" + re.escape(key) + r"\b")
    hits = []
    for name, text in files.items():
        if family == "option":
            ok = pat.search(text) or element.search(text)
        elif family == "constitutive_model":
            ok = pat.search(text)
        else:
            ok = pat.search(text) and (family in text)
        if ok:
            hits.append(name)
    return hits


def sources_reading(key):
    pat = quoted(key)
    hits = []
    for f in sorted((ROOT / "models").rglob("*.cpp")):
        if pat.search(f.read_text(errors="replace")):
            hits.append(f.stem)
    return hits


def short(names, n=4):
    if not names:
        return "—"
    s = ", ".join(names[:n])
    return s + (f" (+{len(names) - n})" if len(names) > n else "")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tephra", default=str(ROOT / "build" / "bin" / "tephra"))
    ap.add_argument("--write", action="store_true", help="replace the audit block of docs/models/README.md")
    a = ap.parse_args()
    files = test_files()
    rows, gaps = [], []
    for family, keys in FAMILIES.items():
        reg = listed(a.tephra, family)
        for key in keys:
            is_reg = reg is not None and key in reg
            tests = tests_naming(files, family, key)
            state = "registered, tested"
            if not is_reg:
                state = "NOT REGISTERED"
            elif not tests:
                state = "NO TEST"
            if state != "registered, tested":
                gaps.append((family, key, state))
            rows.append((family, key, "yes" if is_reg else "no", "—", short(tests), state))
    for key in OPTIONS:
        src = sources_reading(key)
        tests = tests_naming(files, "option", key)
        state = "read, tested"
        if not src:
            state = "READ BY NO MODEL"
        elif not tests:
            state = "NO TEST"
        if state != "read, tested":
            gaps.append(("option", key, state))
        rows.append(("option", key, "—", short(src, 3), short(tests), state))
    lines = ["| family | key | `--list` | read by (models/) | tests naming it | state |",
             "| --- | --- | --- | --- | --- | --- |"]
    lines += [f"| {f} | {k} | {r} | {s} | {t} | {st} |" for f, k, r, s, t, st in rows]
    table = "\n".join(lines)
    print(table)
    print(f"\n{len(rows)} keys, {len(gaps)} gaps" + ("".join(f"\n  {f} {k}: {s}" for f, k, s in gaps)))
    if a.write:
        text = README.read_text()
        if BEGIN not in text or END not in text:
            sys.exit(f"{README} has no {BEGIN} ... {END} block")
        head, rest = text.split(BEGIN, 1)
        _, tail = rest.split(END, 1)
        README.write_text(head + BEGIN + "\n" + table + "\n" + END + tail)
    return 1 if gaps else 0


if __name__ == "__main__":
    sys.exit(main())
