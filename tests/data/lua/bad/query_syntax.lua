component { label = "floor", size = { 10, 2.5, 10 } }
for c in query("floor and") do end
