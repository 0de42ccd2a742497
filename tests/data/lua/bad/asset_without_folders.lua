local bed = componentFromFile("no_such_asset")
