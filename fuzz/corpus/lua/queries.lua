-- Small program for the fuzzer: roots from a polygon and a box, splits, queries with labels,
-- attributes, parents and occlusion, a subtraction and an extrusion.
component { label = "lot", polygon = { { 0, 0 }, { 12, 0 }, { 12, 8 }, { 6, 8 }, { 6, 5 }, { 0, 5 } } }
component { label = "block", size = { 6, 3, 4 }, position = { 1, 0, 1 } }
for c in query("block") do
  split(c, "x", { label = "room", rel = 1 }, { label = "hall", abs = 1.5 }, { label = "room", rel = 2 })
end
for c in query("room or hall") do
  set(c, "kind", get(c, "label") or "none")
end
for c in query("room and not parent(hall) and occlusion(hall) > 0") do
  subtract(c, query("hall"), { label = "cut" })
end
for c in query("cut") do
  local faces = fquery(c, "SIDE")
  if #faces > 0 then extrude(faces, -0.1, { label = "wall" }) end
end
print(#rquery("door"), #roots())
