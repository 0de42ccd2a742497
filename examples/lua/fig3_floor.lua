-- Seed 001, Fig. 3 transcribed to Lua: one floor split into two living spaces around two
-- corridors, the living spaces into apartments, an elevator shaft subtracted from the apartments
-- and corridors it overlaps (the result components are the "rooms", Fig. 2 (B)), the walls and
-- floors of every room extruded inward together (Fig. 2 (C), Fig. 6), doors on the apartment
-- walls that face a corridor, found by occlusion (Fig. 2 (D), §4.4), and the solid geometry.
--
--   insula build examples/lua/fig3_floor.lua -o fig3.glb --report fig3.json

-- Main component.
component { label = "floor", size = { 10, 2.5, 10 } }

-- Creation of the apartments.
for c in query("floor") do
  split(c, "2", { label = "living space", rel = 1 },
    { label = "corridor", abs = 2 },
    { label = "corridor", abs = 2 },
    { label = "living space", rel = 1 })
end
for c in query("'living space'") do
  split(c, "X", { label = "apartment", rel = 1 },
    { label = "apartment", rel = 1 })
end

-- Creation of the elevator shaft (A).
component { label = "elevator", size = { 2, 2.5, 2 }, position = { 4, 0, 2 } }

-- Creation of rooms cut by the elevator shaft (B).
for c in query("apartment or corridor") do
  subtract(c, query("elevator"), { label = "room" })
end

-- Extrusion of room walls, with a color attribute (C).
local i = 0
for c in query("room") do
  local faces = {}
  for _, f in ipairs(fquery(c, "SIDE or BOTTOM")) do
    faces[#faces + 1] = component(c, { label = "wall", boundary = f })
  end
  extrude(faces, -0.05, { label = "iwall", color = i })
  i = i + 1
end

-- Creation of doors by using regions (D): walls of rooms that are not corridors but touch one.
for c in query("wall and not parent(corridor) and occlusion(corridor) > 0") do
  local r = region(c, { label = "door", min = { 0.5, 0, 0 }, max = { c.size[1] - 1.5, 0, 0 } })
end
for _, r in ipairs(rquery("door")) do
  door(r, { width = 0.9, height = 2.1 })
end

-- Creation of the actual geometry.
for c in query("iwall") do
  solidGeometry(c, c.color)
end
