local width = = 4
