#!/usr/bin/python3
"""Write POV-Ray scenes with VTK's vtkPOVExporter, as a VTK user does: build
a pipeline and a render window, then export the window to a .pov file.

Usage: gen_vtk.py OUTDIR
Every scene comes from VTK's own sources and filters (no data files).
"""
import os
import sys

import vtk


def actor(source, color=None, scalars=False, opacity=1.0, specular=0.0):
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    if not scalars:
        mapper.ScalarVisibilityOff()
    a = vtk.vtkActor()
    a.SetMapper(mapper)
    if color:
        a.GetProperty().SetColor(*color)
    a.GetProperty().SetOpacity(opacity)
    a.GetProperty().SetSpecular(specular)
    return a


def sphere():
    s = vtk.vtkSphereSource()
    s.SetThetaResolution(32)
    s.SetPhiResolution(16)
    return [actor(s, (0.9, 0.4, 0.2), specular=0.5)]


def cone_cube():
    c = vtk.vtkConeSource()
    c.SetResolution(24)
    b = vtk.vtkCubeSource()
    b.SetCenter(1.5, 0, 0)
    return [actor(c, (0.2, 0.6, 0.9)), actor(b, (0.8, 0.8, 0.1))]


def elevation():
    p = vtk.vtkPlaneSource()
    p.SetResolution(40, 40)
    w = vtk.vtkWarpScalar()
    e = vtk.vtkElevationFilter()
    s = vtk.vtkSphereSource()
    s.SetThetaResolution(40)
    s.SetPhiResolution(40)
    e.SetInputConnection(s.GetOutputPort())
    e.SetLowPoint(0, -0.5, 0)
    e.SetHighPoint(0, 0.5, 0)
    del w, p
    return [actor(e, scalars=True)]


def superquadric():
    q = vtk.vtkSuperquadricSource()
    q.SetThetaResolution(32)
    q.SetPhiResolution(32)
    q.SetPhiRoundness(0.3)
    q.SetThetaRoundness(1.5)
    q.ToroidalOn()
    return [actor(q, (0.6, 0.3, 0.8), specular=0.3)]


def contour():
    s = vtk.vtkSampleFunction()
    q = vtk.vtkQuadric()
    q.SetCoefficients(0.5, 1, 0.2, 0, 0.1, 0, 0, 0.2, 0, 0)
    s.SetImplicitFunction(q)
    s.SetSampleDimensions(30, 30, 30)
    c = vtk.vtkContourFilter()
    c.SetInputConnection(s.GetOutputPort())
    c.GenerateValues(4, 0.0, 1.2)
    return [actor(c, scalars=True, opacity=1.0)]


def glyphs():
    s = vtk.vtkSphereSource()
    s.SetThetaResolution(12)
    s.SetPhiResolution(12)
    n = vtk.vtkPolyDataNormals()
    n.SetInputConnection(s.GetOutputPort())
    a = vtk.vtkArrowSource()
    g = vtk.vtkGlyph3D()
    g.SetInputConnection(n.GetOutputPort())
    g.SetSourceConnection(a.GetOutputPort())
    g.SetVectorModeToUseNormal()
    g.SetScaleFactor(0.15)
    return [actor(s, (0.9, 0.9, 0.9)), actor(g, (0.9, 0.2, 0.2))]


def tubes():
    h = vtk.vtkParametricSpline()
    pts = vtk.vtkPoints()
    for i in range(12):
        import math
        t = i * 0.6
        pts.InsertNextPoint(math.cos(t), math.sin(t), 0.15 * t)
    h.SetPoints(pts)
    f = vtk.vtkParametricFunctionSource()
    f.SetParametricFunction(h)
    t = vtk.vtkTubeFilter()
    t.SetInputConnection(f.GetOutputPort())
    t.SetRadius(0.08)
    t.SetNumberOfSides(12)
    return [actor(t, (0.3, 0.8, 0.4), specular=0.6)]


def klein():
    k = vtk.vtkParametricFunctionSource()
    k.SetParametricFunction(vtk.vtkParametricFigure8Klein())
    k.SetUResolution(60)
    k.SetVResolution(30)
    return [actor(k, (0.9, 0.7, 0.3))]


def text3d():
    t = vtk.vtkVectorText()
    t.SetText('VTK')
    e = vtk.vtkLinearExtrusionFilter()
    e.SetInputConnection(t.GetOutputPort())
    e.SetExtrusionTypeToNormalExtrusion()
    e.SetVector(0, 0, 1)
    e.SetScaleFactor(0.5)
    return [actor(e, (0.2, 0.3, 0.9))]


def platonic():
    out = []
    colors = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (0, 1, 1)]
    for i in range(5):
        p = vtk.vtkPlatonicSolidSource()
        p.SetSolidType(i)
        tf = vtk.vtkTransform()
        tf.Translate(2.2 * i - 4.4, 0, 0)
        f = vtk.vtkTransformPolyDataFilter()
        f.SetInputConnection(p.GetOutputPort())
        f.SetTransform(tf)
        out.append(actor(f, colors[i]))
    return out


def delaunay():
    import random
    rng = random.Random(4)
    pts = vtk.vtkPoints()
    for _ in range(150):
        x, y = rng.uniform(-1, 1), rng.uniform(-1, 1)
        pts.InsertNextPoint(x, y, 0.3 * (x * x - y * y))
    pd = vtk.vtkPolyData()
    pd.SetPoints(pts)
    d = vtk.vtkDelaunay2D()
    d.SetInputData(pd)
    e = vtk.vtkElevationFilter()
    e.SetInputConnection(d.GetOutputPort())
    e.SetLowPoint(0, 0, -0.3)
    e.SetHighPoint(0, 0, 0.3)
    return [actor(e, scalars=True)]


def transparent():
    a = vtk.vtkSphereSource()
    a.SetRadius(1.0)
    a.SetThetaResolution(30)
    a.SetPhiResolution(30)
    b = vtk.vtkCubeSource()
    b.SetXLength(0.8)
    b.SetYLength(0.8)
    b.SetZLength(0.8)
    return [actor(b, (0.9, 0.1, 0.1)),
            actor(a, (0.5, 0.7, 1.0), opacity=0.4)]


SCENES = [sphere, cone_cube, elevation, superquadric, contour, glyphs,
          tubes, klein, text3d, platonic, delaunay, transparent]


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for make in SCENES:
        ren = vtk.vtkRenderer()
        ren.SetBackground(0.1, 0.2, 0.4)
        win = vtk.vtkRenderWindow()
        win.SetOffScreenRendering(1)
        win.SetSize(640, 480)
        win.AddRenderer(ren)
        for a in make():
            ren.AddActor(a)
        ren.ResetCamera()
        cam = ren.GetActiveCamera()
        cam.Azimuth(30)
        cam.Elevation(20)
        ren.ResetCameraClippingRange()
        exp = vtk.vtkPOVExporter()
        exp.SetRenderWindow(win)
        exp.SetFileName(os.path.join(out, 'vtk_' + make.__name__ + '.pov'))
        exp.Write()


if __name__ == '__main__':
    main()
