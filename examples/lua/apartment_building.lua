-- A multi-storey apartment building with three wings (seed 001, Fig. 1): every wing is sliced
-- into storeys, each storey into two bands of apartments on both sides of a corridor, each
-- apartment into a living room, a bedroom and a bathroom. A stairwell per wing crosses every
-- storey and is cut out of what it overlaps; apartment walls snap onto its sides (§3.5). Walls
-- and floors grow inward per room, the façade of the merged wings (§4.3) outward; doors lead from
-- the corridor into each living room, from the living room into the bedroom and from the bedroom
-- into the bathroom (found by occlusion, §4.4); windows on the façade, a balcony with its door on
-- each living room, and furniture on floor regions clear of the doors (§4.5). The largest example:
-- bench/lua_bench.cc times it (docs/PERFORMANCE.md).
--
--   insula build examples/lua/apartment_building.lua --assets examples/lua/assets -o apartments.glb
--   insula build ... --set storeys=4 --set seed=3   (fewer storeys, another layout draw)

local P = params or {}
local STOREYS = tonumber(P.storeys) or 10
local H = 3.0
math.randomseed(tonumber(P.seed) or 1)

-- Wings: a U of three touching boxes (x along the street, z into the block).
local wings = {
  component { size = { 66, STOREYS * H, 14 }, position = { 0, 0, 0 }, label = "wing", name = "south" },
  component { size = { 14, STOREYS * H, 40 }, position = { 0, 0, 14 }, label = "wing", name = "west" },
  component { size = { 14, STOREYS * H, 40 }, position = { 52, 0, 14 }, label = "wing", name = "east" },
}
-- Stairwells: one per wing, in the band behind the corridor, across every storey.
-- Children of their wings (§3.4.3 instancing, in the wing's space).
local stairs = {
  instance(wings[1], { size = { 3.2, STOREYS * H, 6 }, position = { 31.4, 0, 8 }, label = "stair" }),
  instance(wings[2], { size = { 6, STOREYS * H, 3.2 }, position = { 8, 0, 16 }, label = "stair" }),
  instance(wings[3], { size = { 6, STOREYS * H, 3.2 }, position = { 0, 0, 16 }, label = "stair" }),
}

-- Storeys, corridor and apartment bands. The south wing runs along x, the others along z.
for _, wing in ipairs(wings) do
  local across = wing.size[1] > wing.size[3] and "z" or "x"
  for i, s in ipairs(slice(wing, "y", H, { label = "storey" })) do
    s.level = i - 1
    split(s, across, { label = "band", rel = 1 }, { label = "corridor", abs = 2.0 },
      { label = "band", rel = 1 })
  end
end
for band in query("band") do
  local along = band.size[1] > band.size[3] and "x" or "z"
  -- Apartments of about 7 m; their walls snap onto a stairwell's sides within 2 m (§3.5).
  slice(band, along, 6.5 + math.random() * 1.5,
    { leftover = "spread", constraints = snap(stairs, 2.0), label = "apartment" })
end
for apt in query("apartment") do
  local along = apt.size[1] > apt.size[3] and "x" or "z"
  split(apt, along, { label = "living", rel = 1.6 }, { label = "bedroom", rel = 1 },
    { label = "bath", abs = 2.2 })
end
for c in query("living or bedroom or bath or corridor") do
  subtract(c, stairs, { label = "space" })
end

-- Base geometry (§4.2).
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
for _, s in ipairs(stairs) do line_inside(s, 0.15) end

-- The façade of the merged wings (§4.3): one shell, grown outward with roof and foundation.
local shell = union(wings, { label = "shell" })[1]
local facade = {}
for _, f in ipairs(fquery(shell, "ALL")) do
  facade[#facade + 1] = component(shell, { boundary = f, label = "facade" })
end
extrude(facade, 0.3, { label = "ewall" })

-- Openings (§4.4): by occlusion between neighbouring spaces, storey by storey.
local function door_on(w, width)
  if w.size[1] < width + 1.0 then return nil end
  local r = region(w, { label = "door", min = { 0.4, 0, 0 }, max = { w.size[1] - 0.4, 0, 0 } })
  return door(r, { width = width, height = 2.1 })
end
-- Each query runs once over the whole building: its occlusion group is gathered once.
for w in query("wall and parent(living) and occlusion(corridor) > 0.9") do door_on(w, 1.0) end
for w in query("wall and parent(bedroom) and occlusion(living) > 0.9") do door_on(w, 0.8) end
for w in query("wall and parent(bath) and occlusion(bedroom) > 0.9") do door_on(w, 0.7) end
for w in query("wall and parent(stair) and occlusion(corridor) > 0") do
  for level = 0, STOREYS - 1 do
    door(w, { u = w.size[1] / 2, sill = level * H + 0.1, width = 1.2, height = 2.1 })
  end
end
for w in query("wall and (parent(bedroom) or parent(bath)) and occlusion(facade) > 0.9") do
  window(w, { u = w.size[1] / 2, sill = 0.9, width = math.min(1.4, w.size[1] - 0.6), height = 1.4 })
end
for w in query("wall and parent(corridor) and occlusion(facade) > 0.9") do
  window(w, { u = w.size[1] / 2, sill = 0.6, width = 1.0, height = 2.0 })
end
-- Living rooms: a window and a balcony door onto a balcony hung on the façade (w.level is the
-- storey's level, inherited).
for w in query("wall and parent(living) and occlusion(facade) > 0.9") do
  if w.size[1] > 2.6 then
    local u = w.size[1] / 2
    window(w, { u = u - 0.7, sill = 0.9, width = 0.8, height = 1.4 })
    door(w, { u = u + 0.5, sill = 0, width = 0.9, height = 2.2, label = "balcony door" })
    if w.level > 0 then
      local r = region(w, { label = "balcony", min = { u - 0.2, 0, 1.0 }, max = { u + 0.2, 0, 1.0 } })
      place(r, "balcony", { kind = "installation", label = "balcony" })
    end
  end
end

-- Stairwells: sliced at the storey floors (§3.5), one flight per storey.
for _, stair in ipairs(stairs) do
  local floors = query("storey")
  local wide = stair.size[1] > stair.size[3]
  for _, flight in ipairs(sliceAt(stair, "y", snap(floors, 0), { label = "flight" })) do
    local n, run = 16, 5.2 / 16
    for k = 0, n - 1 do
      local size = wide and { run, (k + 1) * H / n, 1.2 } or { 1.2, (k + 1) * H / n, run }
      local at = wide and { 0.4 + k * run, 0, 0.25 } or { 0.25, 0, 0.4 + k * run }
      instance(flight, { position = at, size = size, label = "step" })
    end
  end
end

-- Furniture (§4.5), shared meshes placed on floor regions clear of the doors. A list, not a table
-- keyed by room kind: pairs() visits keys in an order Lua varies from run to run, and the parts
-- would then come out in another order each time.
local furniture = {
  { "living", { { "sofa", 1.2 }, { "table", 1.0 }, { "chair", 0.6 }, { "chair", 0.6 }, { "shelf", 0.6 } } },
  { "bedroom", { { "bed", 1.3 }, { "wardrobe", 0.8 }, { "desk", 0.9 }, { "chair", 0.5 } } },
  { "bath", { { "plant", 0.4 } } },
}
for _, entry in ipairs(furniture) do
  local kind, items = entry[1], entry[2]
  for room in query("space and parent(" .. kind .. ")") do
    local sx, sz = room.size[1], room.size[3]
    local avoid = {}
    for d in query("door", room) do avoid[#avoid + 1] = d end
    for _, item in ipairs(items) do
      local m = item[2]
      if sx > 2 * m and sz > 2 * m then
        local r = region(room, { label = "floor", min = { m, 0.1, m }, max = { sx - m, 0.1, sz - m } })
        local piece = place(r, item[1], { avoid = avoid, clearance = 0.25, label = "furniture" })
        if piece then avoid[#avoid + 1] = piece end
      end
    end
    -- A ceiling lamp in the middle of every room.
    local lamp = region(room, { label = "ceiling", min = { sx / 2, H - 0.5, sz / 2 }, max = { sx / 2, H - 0.5, sz / 2 } })
    place(lamp, "lamp", { label = "lamp" })
  end
end

solidGeometry(query("iwall or ewall"), { uv = 1.0 })
