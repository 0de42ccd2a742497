# Writes examples/osm/town.osm: a hand-written OpenStreetMap file in the form of an export, with
# Simple 3D Buildings tags (local meters -> lon/lat near 47.2655 N, 11.3935 E).
import math
lat0, lon0 = 47.2655, 11.3935
def ll(x, y):
    return (lon0 + x / (111320 * math.cos(math.radians(lat0))), lat0 + y / 110574)
nodes = []; ways = []; rels = []
nid = [1000]; wid = [2000]; rid = [3000]
def node(x, y):
    nid[0] += 1; lon, lat = ll(x, y); nodes.append((nid[0], lat, lon)); return nid[0]
def way(pts, tags=None):
    ids = [node(x, y) for x, y in pts]; ids.append(ids[0])
    wid[0] += 1; ways.append((wid[0], ids, tags or {})); return wid[0]
def rect(x, y, w, h): return [(x, y), (x + w, y), (x + w, y + h), (x, y + h)]
def rot(pts, cx, cy, deg):
    a = math.radians(deg); c, s = math.cos(a), math.sin(a)
    return [(cx + (x - cx) * c - (y - cy) * s, cy + (x - cx) * s + (y - cy) * c) for x, y in pts]
# A church: the outline is replaced by its parts (nave, tower with a spire-like pyramid, apse).
way(rect(-7, 0, 41, 14), {"building": "church", "name": "St. Example", "height": "48"})
way(rect(0, 0, 28, 14), {"building:part": "yes", "height": "17", "roof:shape": "gabled",
                          "roof:height": "7", "building:colour": "#efe8d8", "roof:colour": "#7a4030"})
way(rect(28, 3, 6, 8), {"building:part": "yes", "height": "12", "roof:shape": "hipped",
                         "roof:height": "3", "building:colour": "#efe8d8", "roof:colour": "#7a4030"})
way(rect(-7, 3.5, 7, 7), {"building:part": "yes", "height": "48", "roof:shape": "pyramidal",
                           "roof:height": "14", "building:colour": "#e6dcc6",
                           "roof:material": "copper"})
# A courtyard block: a multipolygon with a hole.
outer = way(rect(50, -5, 42, 30)); inner = way(rect(60, 3, 22, 14))
rid[0] += 1
rels.append((rid[0], [("way", outer, "outer"), ("way", inner, "inner")],
             {"type": "multipolygon", "building": "apartments", "building:levels": "4",
              "roof:shape": "hipped", "roof:levels": "1", "building:colour": "#e8d8b0",
              "roof:material": "roof_tiles"}))
# A row of houses with gables toward the street, their roofs in several S3DB shapes.
shapes = ["gabled", "half-hipped", "gambrel", "saltbox", "gabled", "mansard"]
colours = ["#f2e6c8", "white", "#d9c3a0", "#c8d0d8", "#f0d8c8", "#e0e0d0"]
for i, (shape, colour) in enumerate(zip(shapes, colours)):
    tags = {"building": "house", "building:levels": "2", "roof:shape": shape, "roof:height": "4",
            "building:colour": colour, "roof:colour": "#8a4a38"}
    if shape == "saltbox": tags["roof:direction"] = "S"
    if i == 4: tags["roof:orientation"] = "across"
    way(rect(i * 11, -30, 9, 12), tags)
# A chapel with a dome, an octagon.
way([(110 + 6 * math.cos(math.radians(22.5 + 45 * k)), -20 + 6 * math.sin(math.radians(22.5 + 45 * k))) for k in range(8)],
    {"building": "chapel", "height": "14", "roof:shape": "dome", "roof:height": "5",
     "roof:colour": "#5e9c84", "building:colour": "#f5f0e6"})
# Two offices joined by a bridge that starts 6 m above the street.
way(rect(110, 10, 16, 16), {"building": "office", "height": "20 m", "building:material": "glass"})
way(rect(136, 10, 16, 16), {"building": "office", "height": "66'", "building:material": "concrete"})
way(rect(126, 15, 10, 5), {"building:part": "yes", "min_height": "6", "height": "10",
                            "building:colour": "#9aa0a6"})
# A carport: a roof on posts.
way(rect(78, -30, 6, 5), {"building": "roof", "height": "3", "roof:shape": "skillion",
                           "roof:height": "0.6", "roof:direction": "E"})
# A rotated house with a round (barrel) roof and one with an onion on a tower.
way(rot(rect(90, -34, 8, 14), 94, -27, 11), {"building": "yes", "height": "8", "roof:shape": "round",
                                              "roof:height": "3"})
way(rect(140, -26, 6, 6), {"building": "tower", "height": "22", "roof:shape": "onion",
                            "roof:height": "6", "roof:colour": "#6a8a3a"})
out = ['<?xml version="1.0" encoding="UTF-8"?>',
       '<osm version="0.6" generator="hand-written for Insula (examples/osm/README.md)">']
for i, lat, lon in nodes:
    out.append(f'  <node id="{i}" version="1" lat="{lat:.7f}" lon="{lon:.7f}"/>')
def tags_xml(tags): return [f'    <tag k="{k}" v="{v}"/>' for k, v in tags.items()]
for i, ids, tags in ways:
    out.append(f'  <way id="{i}" version="1">')
    out += [f'    <nd ref="{n}"/>' for n in ids] + tags_xml(tags) + ['  </way>']
for i, members, tags in rels:
    out.append(f'  <relation id="{i}" version="1">')
    out += [f'    <member type="{t}" ref="{r}" role="{role}"/>' for t, r, role in members]
    out += tags_xml(tags) + ['  </relation>']
out.append('</osm>')
open(__file__.replace('make_town.py', 'town.osm'), 'w').write('\n'.join(out) + '\n')
