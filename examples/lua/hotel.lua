-- A small hotel (seed 001, Fig. 10 left): four storeys of guest rooms on both sides of a central
-- corridor, a stairwell across every storey cut out of the rooms and corridors it overlaps, walls
-- grown inward per room and a façade grown outward (§4.2), doors to the corridor found by
-- occlusion (§4.4), one window per room on the façade, and beds, wardrobes and desks placed on
-- floor regions clear of the doors (§4.5).
--
--   insula build examples/lua/hotel.lua --assets examples/lua/assets -o hotel.glb

local W, D, H, STOREYS = 30, 14, 3.2, 4
local ROOM = 4.2 -- nominal room width; the left-over goes to both end rooms (§3.4.3)

local hotel = component { size = { W, STOREYS * H, D }, label = "hotel" }
-- The stairwell spans every storey (§4.1) and the whole depth of the back rooms: a child of the
-- hotel (§3.4.3 instancing, clipped to the hotel's boundary).
local stair = instance(hotel, { size = { 3.0, STOREYS * H, 6 }, position = { 13.5, 0, 8 }, label = "stair" })

-- Space partitioning (§4.1): storeys, then rooms | corridor | rooms.
for i, s in ipairs(slice(hotel, "y", H, { label = "storey" })) do
  s.level = i - 1
end
for s in query("storey") do
  split(s, "z", { label = "rooms", rel = 1 }, { label = "corridor", abs = 2.0 },
    { label = "rooms", rel = 1 })
end
-- Room walls snap onto the stairwell's sides when they come within 1 m of them (§3.5).
for band in query("rooms") do
  slice(band, "x", ROOM, { leftover = "both", constraints = snap(stair, 1.0), label = "room" })
end
for c in query("room or corridor") do
  subtract(c, stair, { label = "space" })
end

-- Base geometry (§4.2): walls and floors of every space grown inward together (Fig. 6).
local function line_inside(c, thickness)
  local faces = {}
  for _, f in ipairs(fquery(c, "SIDE")) do
    faces[#faces + 1] = component(c, { boundary = f, label = "wall" })
  end
  for _, f in ipairs(fquery(c, "BOTTOM")) do
    faces[#faces + 1] = component(c, { boundary = f, label = "floor" })
  end
  extrude(faces, -thickness, { label = "iwall" })
end
for c in query("space") do line_inside(c, 0.1) end
line_inside(stair, 0.15)

-- The façade: the hotel's outer faces grown outward, roof and foundation included.
local shell = {}
for _, f in ipairs(fquery(hotel, "ALL")) do
  shell[#shell + 1] = component(hotel, { boundary = f, label = "facade" })
end
extrude(shell, 0.25, { label = "ewall" })

-- Doors (§4.4): room walls next to the corridor, found by occlusion.
for w in query("wall and parent(room) and occlusion(corridor) > 0") do
  local r = region(w, { label = "door", min = { 0.5, 0, 0 }, max = { w.size[1] - 0.5, 0, 0 } })
  door(r, { width = 0.9, height = 2.1 })
end
-- One window per room on the façade; walls of the corridor ends get a tall window.
for w in query("wall and parent(room) and occlusion(facade) > 0.9") do
  window(w, { u = w.size[1] / 2, sill = 0.9, width = 1.4, height = 1.4 })
end
-- The stairwell opens onto the corridor on every storey (holes above the lowest, a notch there).
for w in query("wall and parent(stair) and occlusion(corridor) > 0") do
  for i = 0, STOREYS - 1 do
    door(w, { u = w.size[1] / 2, sill = i * H + 0.1, width = 1.0, height = 2.1 })
  end
end
for w in query("wall and parent(corridor) and occlusion(facade) > 0.9") do
  window(w, { u = w.size[1] / 2, sill = 0.6, width = 1.0, height = 2.0 })
end

-- Stairs: the stairwell sliced at the storey floors (§3.5's specialised slice), a flight per storey.
local floors = {}
for s in query("storey") do floors[#floors + 1] = s end
for _, flight in ipairs(sliceAt(stair, "y", snap(floors, 0), { label = "flight" })) do
  local steps, run = 16, 5.2 / 16
  for k = 0, steps - 1 do
    instance(flight, { position = { 0.3, 0, 0.4 + k * run }, size = { 1.1, (k + 1) * H / steps, run },
      label = "step" })
  end
end

-- Furniture (§4.5): on a floor region of each room, clear of its door (with the leaf's swing).
for room in query("space and parent(room)") do
  local sx, sz = room.size[1], room.size[3]
  local doors = query("door", room)
  local taken = {}
  for _, item in ipairs({ { "bed", 1.4 }, { "wardrobe", 0.9 }, { "desk", 1.0 }, { "chair", 0.5 } }) do
    local margin = item[2]
    if sx > 2 * margin and sz > 2 * margin then
      local r = region(room, { label = "floor", min = { margin, 0.1, margin }, max = { sx - margin, 0.1, sz - margin },
        minAngles = { 0, 0, 0 }, maxAngles = { 0, 0, 0 } })
      local avoid = {}
      for d in doors do avoid[#avoid + 1] = d end
      for _, t in ipairs(taken) do avoid[#avoid + 1] = t end
      local piece = place(r, item[1], { avoid = avoid, clearance = 0.3, label = "furniture" })
      if piece then taken[#taken + 1] = piece end
    end
  end
end

-- Geometry (§3.6): solids with every door and window cut, texture coordinates per 1 m tile.
solidGeometry(query("iwall or ewall"), { uv = 1.0 })
