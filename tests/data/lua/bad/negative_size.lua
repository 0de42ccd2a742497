component { label = "box", size = { 4, -1, 3 } }
