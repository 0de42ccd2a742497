component { label = "box", size = { 1, 1 } }
