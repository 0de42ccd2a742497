-- A house on the graph's lot: a yard border, walls, a gable roof.
local parts = offset(lot, -1.5, {pieces={{label="core"}, {label="yard"}}})
local mass = extrude(parts[1], params.height or 9, {label="mass"})[1]
comp(mass, "faces", "side", {label="wall"})
local top = comp(mass, "faces", "top", {label="top"})[1]
roof(top, "gable", 35, 0.3, {label="roof"})
