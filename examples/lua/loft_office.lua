-- A loft-style office building (seed 001, Fig. 10 middle): three open-plan storeys around a
-- service core (stairs), ribbon windows on the façade, and a row of meeting rooms along the back
-- whose partition walls are pushed off the windows by repulsion constraints (§3.5, Fig. 7: "to
-- avoid having perpendicular walls crossing a window"). Desks stand in rows on the open floor,
-- plants where there is room left (§4.5).
--
--   insula build examples/lua/loft_office.lua --assets examples/lua/assets -o loft.glb

local W, D, H, STOREYS = 36, 18, 4.0, 3
local office = component { size = { W, STOREYS * H, D }, label = "office" }
local core = instance(office, { size = { 8, STOREYS * H, 6 }, position = { 14, 0, 7 }, label = "core" })

-- The façade first: its windows are the constraints the partitions avoid.
local shell = {}
for _, f in ipairs(fquery(office, "ALL")) do
  shell[#shell + 1] = component(office, { boundary = f, label = "facade" })
end
for _, f in ipairs(shell) do
  local n = f.normal
  if math.abs(f.size[2] - STOREYS * H) < 1e-6 then -- a side face (not the roof or the ground)
    local bays = math.floor(f.size[1] / 3.0)
    local bay = f.size[1] / bays
    for level = 0, STOREYS - 1 do
      for b = 0, bays - 1 do
        window(f, { u = (b + 0.5) * bay, sill = level * H + 0.8, width = bay - 0.9, height = 2.6 })
      end
    end
  end
end
extrude(shell, 0.3, { label = "ewall" })

-- Storeys: open floor in front, a band of meeting rooms along the back façade.
local windows = repel(query("window"), 0.25)
for i, s in ipairs(slice(office, "y", H, { label = "storey" })) do
  s.level = i - 1
  -- The band's wall also keeps off the windows of the end façades.
  constrainedSplit(s, "z", windows, { label = "open", rel = 1 }, { label = "meeting band", abs = 5.0 })
end
for band in query("'meeting band'") do
  constrainedSplit(band, "x", windows, { label = "meeting", abs = 5.0 }, { label = "meeting", abs = 5.0 },
    { label = "meeting", abs = 5.0 }, { label = "lounge", rel = 1 }, { label = "meeting", abs = 5.0 },
    { label = "meeting", abs = 5.0 })
end
for c in query("open or meeting or lounge") do
  subtract(c, core, { label = "space" })
end

-- Walls and floors inward (§4.2), the core's walls thicker.
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
for c in query("space") do line_inside(c, 0.08) end
line_inside(core, 0.2)

-- Doors: meeting rooms and the lounge open onto the open floor; the core on every storey.
for w in query("wall and (parent(meeting) or parent(lounge)) and occlusion(open) > 0") do
  local r = region(w, { label = "door", min = { 0.6, 0, 0 }, max = { w.size[1] - 0.6, 0, 0 } })
  door(r, { width = 1.0, height = 2.4 })
end
for w in query("wall and parent(core) and occlusion(open) > 0") do
  for level = 0, STOREYS - 1 do
    door(w, { u = w.size[1] / 2, sill = level * H + 0.08, width = 1.4, height = 2.4 })
  end
end

-- Stairs in the core, one flight per storey (the core sliced at the storeys' floors, §3.5).
for _, flight in ipairs(sliceAt(core, "y", snap(query("storey"), 0), { label = "flight" })) do
  local n, run = 20, 4.8 / 20
  for k = 0, n - 1 do
    instance(flight, { position = { 0.4 + k * run, 0, 0.4 }, size = { run, (k + 1) * H / n, 1.4 },
      label = "step" })
  end
end

-- Desks in rows on the open floor, chairs behind them; a meeting table per meeting room.
for open in query("space and parent(open)") do
  local sx, sz = open.size[1], open.size[3]
  local avoid = {}
  for d in query("door") do avoid[#avoid + 1] = d end
  for x = 2.0, sx - 2.0, 2.4 do
    for z = 1.8, sz - 1.5, 3.2 do
      local spot = region(open, { label = "desk", min = { x, 0.08, z }, max = { x, 0.08, z } })
      local desk = place(spot, "desk", { avoid = avoid, clearance = 0.6, attempts = 1, label = "desk" })
      if desk then
        avoid[#avoid + 1] = desk
        local seat = region(open, { label = "seat", min = { x, 0.08, z - 0.75 }, max = { x, 0.08, z - 0.75 } })
        place(seat, "chair", { attempts = 1, label = "chair" })
      end
    end
  end
  local r = region(open, { label = "plants", min = { 0.8, 0.08, 0.8 }, max = { sx - 0.8, 0.08, sz - 0.8 } })
  for _ = 1, 6 do
    local p = place(r, "plant", { avoid = avoid, clearance = 0.3, label = "plant" })
    if p then avoid[#avoid + 1] = p end
  end
end
for room in query("space and parent(meeting)") do
  local r = region(room, { label = "table", min = { room.size[1] / 2, 0.08, room.size[3] / 2 },
    max = { room.size[1] / 2, 0.08, room.size[3] / 2 } })
  place(r, "table", { label = "table" })
  for _, dx in ipairs({ -0.4, 0.4 }) do
    for _, dz in ipairs({ -0.65, 0.65 }) do
      local s = region(room, { label = "seat", min = { room.size[1] / 2 + dx, 0.08, room.size[3] / 2 + dz },
        max = { room.size[1] / 2 + dx, 0.08, room.size[3] / 2 + dz } })
      place(s, "chair", { label = "chair" })
    end
  end
end

solidGeometry(query("iwall or ewall"), { uv = 1.0 })
