"""The entry page's numbers and table from the CSVs: the table of the
shipped scenes (README.md, `<!-- table: scenes -->`: a thumbnail, what
each shows and its run time from doc/benchmarks/scene-times.csv) and the
times of the two README commands (first-hour.csv). A scene without a
line in SCENE_POINTS, a time or a picture is an error of the docs test
(docs/tables_from_csv): a new scene must be shown and timed.
"""
import glob
import os

from doc_table_builders import markdown, rows, seconds

# What each shipped scene shows, in the words of the table.
SCENE_POINTS = {
    "example1": "Kanno's example I: a 2D cantilever (plane stress) pushed onto a rigid floor with friction, solved with the paper's method",
    "example2": "Kanno's example II: the 3D brick on the floor",
    "press_and_drag": "a loading history on example I's body: press, hold, drag the floor until the contact slides, unload",
    "hertz_2d": "Hertz's line contact: a half disc on a frictionless plane, against Hertz's pressure",
    "hertz_3d": "Hertz's point contact: a half ball on a frictionless plane, refined near the contact",
    "hertz_3d_rubber": "a rubber ball (nu = 0.4999) on a plane, the mesh adapted: the B-bar element keeps Hertz within 1 %",
    "cattaneo_2d": "Cattaneo-Mindlin: the half disc pressed, then pulled sideways: stick in the middle, slip at the edges",
    "cattaneo_3d": "Cattaneo-Mindlin in 3D: the stick radius under a tangential force",
    "sliding_block": "a block pressed and dragged: it sticks, then slides with T = mu N",
    "roller_2d": "a mesh from a Gmsh file: a half disc pressed and pulled sideways",
    "roller_3d": "a half cylinder from a Gmsh file (hexahedra) pressed along its length and pulled",
    "block_on_block_2d": "two deformable bodies, their meshes not matching (dual mortar): a block pressed and dragged over a base",
    "block_on_block_3d": "the same in 3D",
    "ball_on_plate": "Hertz between two elastic bodies of other materials, both meshes adapted to the contact",
    "ball_on_plate_axisymmetric": "the ball on the plate as the axisymmetric section of both bodies: the 3D problem solved in 2D",
    "hertz_axisymmetric": "Hertz's ball on a plane as its axisymmetric section (x = r): the 3D contact radius and pressure from a 2D mesh",
    "ball_indentation_axisymmetric": "a hardness test: a rigid ball pressed into steel (finite-strain J2, Voce) and lifted off, axisymmetric: the impression it leaves, Tabor's hardness",
    "shrink_fit_axisymmetric": "a hub shrunk on a shaft (an interference fit, axisymmetric), then the shaft pushed out: the pressure peaks at the hub's ends, the fit slips from them inwards",
    "flat_punch_2d": "a rigid flat punch from a Gmsh line mesh pressed into a base and dragged until it slides",
    "scratch_3d": "a scratch test: a rigid stylus from an STL file pressed into a slab and dragged",
    "lame_3d": "Lamé's thick sphere of rubber (nu = 0.4999) under internal pressure: the B-bar element against the exact solution",
    "bracket_2d": "two bodies from the user's Gmsh mesh: a stiff bracket pushed over a softer base until its heel lifts and it slides",
    "bracket_3d": "the bracket in 3D",
    "step42_indentation": "deal.II's step-42: an elasto-plastic cube (J2) indented by a rigid ball, the mesh adapted",
    "ironing_2d": "ironing: a rigid die pressed into a neo-Hookean block and slid along it with friction (finite strain)",
    "o_ring_2d": "a rubber cord squeezed by 25 % between two plates (neo-Hookean, finite strain, plane strain: the section of a long straight seal; a ring is o_ring_axisymmetric)",
    "o_ring_axisymmetric": "an O-ring in its groove, axisymmetric: squeezed by 20 % by the bore (nearly incompressible neo-Hookean, friction 0.1 on bore and groove), then pushed onto the back wall by the sealed fluid; it seals where its contact pressure exceeds the fluid's",
    "billet_upsetting": "forming: a quarter of an aluminium billet (J2 with Voce hardening, finite strain) upset by 50 % between plane dies with friction 0.1: it barrels",
    "strip_drawing_2d": "forming: an elasto-plastic strip (finite-strain J2) drawn under a rigid die that takes a fifth off its thickness, with friction 0.1: large sliding, the strip leaves thinner",
    "billet_upsetting_sticking": "the billet upset by 25 % with friction 1: the faces stick, the side folds over onto the die",
}


def shipped_scenes(root):
    return sorted(os.path.basename(p)[:-4]
                  for p in glob.glob(os.path.join(root, "parameters", "*.prm")))


def scenes(root):
    times = {r["scene"]: r for r in rows(root, "scene-times.csv") if r["ranks"] == "1"}
    body = []
    for scene in shipped_scenes(root):
        if scene not in SCENE_POINTS:
            raise KeyError(f"no line for the scene {scene} in bench/doc_table_scenes.py")
        if scene not in times:
            raise KeyError(f"no time for the scene {scene} (bench/scene_times.py --scenes {scene})")
        picture = os.path.join("doc", "figures", scene + ".png")
        if not os.path.isfile(os.path.join(root, picture)):
            raise OSError(f"no picture {picture} (scripts/make_gallery.sh)")
        # A 2D scene's contact is a thin line in the picture: its profile
        # plot (pressure and traction along the contact boundary) beside it.
        profile = os.path.join("doc", "figures", scene + "-profile.png")
        shown = f'<img src="{picture}" width="240">'
        if os.path.isfile(os.path.join(root, profile)):
            shown += f' <img src="{profile}" width="160">'
        body.append([shown, f"`parameters/{scene}.prm`", SCENE_POINTS[scene],
                     seconds(times[scene]["wall_s"])])
    return markdown(["", "scene", "what it shows", "time"], body)


def first_hour_command(index, after):
    def quote(root):
        for r in rows(root, "first-hour.csv"):
            if r["command"] == str(index) and r["after"] == after:
                return f"{int(r['seconds'])} s"
        raise KeyError(f"no row of command {index} in first-hour.csv (bench/first_hour.py)")
    return quote


TABLES = {"scenes": scenes}
QUOTES = {"first-hour-command-1": first_hour_command(1, ""),
          "first-hour-command-2": first_hour_command(2, "1"),
          "first-hour-command-2-alone": first_hour_command(2, "")}
