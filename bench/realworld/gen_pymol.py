#!/usr/bin/python3
"""Write POV-Ray scenes with PyMOL's own exporter (cmd.get_povray), as a
PyMOL user does: build a molecule, pick a representation and a view, save
the header and body that get_povray() returns into one .pov file.

Usage: gen_pymol.py OUTDIR
Molecules are built from PyMOL's fragment library and its peptide builder
(cmd.fab), so no structure file has to be fetched.
"""
import os
import sys

from pymol import cmd

CASES = [
    # name, builder, build argument, representation commands
    ('ala_sticks', 'fragment', 'ala', ['show sticks']),
    ('trp_spheres', 'fragment', 'trp', ['hide everything', 'show spheres']),
    ('phe_ballstick', 'fragment', 'phe',
     ['show sticks', 'show spheres', 'set sphere_scale, 0.25',
      'set stick_radius, 0.15']),
    ('benzene_lines', 'fragment', 'benzene', ['show lines', 'show nonbonded']),
    ('cyclohexane_sticks_white', 'fragment', 'cyclohexane',
     ['show sticks', 'bg_color white']),
    ('helix_cartoon', 'fab', 'AAAAKAAAAKAAAAKA',
     ['hide everything', 'show cartoon', 'spectrum count, rainbow']),
    ('sheet_cartoon', 'fab_sheet', 'VKVKVKVKVK',
     ['hide everything', 'show cartoon', 'color marine']),
    ('helix_ribbon', 'fab', 'GSHMLEDPAAKLLE',
     ['hide everything', 'show ribbon', 'color orange']),
    ('peptide_surface', 'fab', 'KLWE',
     ['hide everything', 'show surface', 'color lightblue']),
    ('peptide_mesh', 'fab', 'DAWK',
     ['hide everything', 'show mesh', 'color green']),
    ('peptide_sticks_cpk', 'fab', 'CHYK',
     ['show sticks', 'util.cbag']),
    ('helix_spheres_transp', 'fab', 'AEAAAKEAAAKA',
     ['hide everything', 'show spheres', 'set sphere_transparency, 0.4',
      'spectrum resi']),
    ('trp_dots', 'fragment', 'trp', ['hide everything', 'show dots']),
    ('helix_sticks_cartoon', 'fab', 'EELLKKAEELLKK',
     ['show cartoon', 'set cartoon_transparency, 0.0',
      'show sticks, sidechain', 'color grey80, elem C']),
]


def build(name, how, arg):
    cmd.reinitialize()
    cmd.viewport(640, 480)
    if how == 'fragment':
        cmd.fragment(arg, name)
    elif how == 'fab':
        cmd.fab(arg, name, ss=1)
    elif how == 'fab_sheet':
        cmd.fab(arg, name, ss=3)
    else:
        raise ValueError(how)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, how, arg, reps in CASES:
        build(name, how, arg)
        for line in reps:
            cmd.do(line)
        cmd.orient()
        cmd.turn('y', 20)
        header, body = cmd.get_povray()
        with open(os.path.join(out, name + '.pov'), 'w') as fh:
            fh.write('// written by PyMOL %s cmd.get_povray()\n'
                     % cmd.get_version()[0])
            fh.write(header)
            fh.write(body)


if __name__ == '__main__':
    main()
