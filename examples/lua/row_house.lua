-- A row of town houses (seed 001, Fig. 9): one block split into houses of random widths (seeded),
-- each house into two storeys, each storey into a hall running front to back and a front and a back
-- room; walls and floors grown inward per space and the block's shell grown outward (§4.2, Fig. 6),
-- one gable roof with its ridge along the street (§3.4.3 roofing), a front door in every hall,
-- doors from the hall into the rooms found by occlusion (§4.4), and windows on every room wall that
-- faces the street or the yard.
--
--   insula build examples/lua/row_house.lua --seed 3 -o row.glb --report row.json

local HOUSES = params.houses or 4
local DEPTH, STOREY, STOREYS = 10, 2.8, 2

-- Space partitioning (§4.1): the block, the houses (5.5 to 7 m wide), storeys, hall and rooms.
local widths = {}
local total = 0
for i = 1, HOUSES do
  widths[i] = 5.5 + math.random() * 1.5
  total = total + widths[i]
end
local row = component { label = "row", size = { total, STOREYS * STOREY, DEPTH } }
local pieces = {}
for i = 1, HOUSES do pieces[i] = { label = "house", abs = widths[i], number = i } end
split(row, "x", pieces)

for h in query("house") do
  for i, s in ipairs(split(h, "y", { label = "storey", rel = 1 }, { label = "storey", rel = 1 })) do
    s.level = i - 1
  end
end
for s in query("storey") do
  split(s, "x", { label = "hall", abs = 1.8 }, { label = "rooms", rel = 1 })
end
for r in query("rooms") do
  split(r, "z", { label = "room", rel = 1, side = "back" }, { label = "room", rel = 1.2, side = "front" })
end

-- Base geometry (§4.2): every space lined inward, its front-facing wall labelled for the doors.
for c in query("hall or room") do
  local faces = {}
  for _, f in ipairs(fquery(c, "SIDE")) do
    local labels = { "wall" }
    if f.normal[2] < -0.9 then labels[2] = "street" end
    faces[#faces + 1] = component(c, { boundary = f, labels = labels })
  end
  for _, f in ipairs(fquery(c, "BOTTOM")) do
    faces[#faces + 1] = component(c, { boundary = f, label = "floor" })
  end
  extrude(faces, -0.1, { label = "iwall" })
end
local shell = {}
for _, f in ipairs(fquery(row, "SIDE or BOTTOM")) do
  shell[#shell + 1] = component(row, { boundary = f, label = "facade" })
end
extrude(shell, 0.25, { label = "ewall" })

-- Roof: one gable over the whole row with its ridge along the street and the gables on the end
-- walls, as the row houses of Fig. 9 (a gable per house would put the ridge on each house's long
-- axis, front to back, and turn the gables to the street).
local top = component(row, { boundary = fquery(row, "TOP")[1], label = "roof base" })
roof(top, "gable", 40, 0.3, { label = "roof" })

-- Architectural elements (§4.4): a front door per house, doors from the hall into each room,
-- a window per room wall on the street or the yard.
for w in query("street and parent(hall) and level == 0") do
  door(w, { u = 0.9, width = 1.0, height = 2.2 })
end
for w in query("wall and parent(room, 1) and occlusion(hall) > 0") do
  door(w, { u = 1.2, width = 0.8, height = 2.05 })
end
for w in query("wall and parent(room, 1) and occlusion(facade) > 0.9") do
  local windows = w.size[1] > 4.5 and 2 or 1
  for k = 1, windows do
    window(w, { u = w.size[1] * k / (windows + 1), sill = 0.9, width = 1.2, height = 1.4 })
  end
end

for c in query("iwall or ewall") do solidGeometry(c) end
