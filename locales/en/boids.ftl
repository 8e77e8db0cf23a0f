# Why a rock, pillar or reef ledge cannot go where it was put or moved
# (src/sim/common/obstacle.rs, src/sim/boids/placement.rs).

boids-obstacle-radius = the radius must be between { $min } m and { $max } m (got { $radius } m)
boids-obstacle-near-the-glass = it must stay at least { $gap } m away from the glass (at ({ $x }, { $z }) m)
boids-obstacle-height-not-a-number = its position and height must be numbers
boids-obstacle-off-the-sand = it must stand on the sand (base at y = { $floor } m, got { $base } m)
boids-obstacle-height = its height must be above 0 m and its top at least { $gap } m below the surface (height { $height } m)
boids-obstacle-rock-not-a-number = the rock's position must be numbers
boids-obstacle-rock-buried = the rock is buried in the sand: raise its centre
boids-obstacle-rock-floats = the rock floats: it must touch the sand
boids-obstacle-rock-too-high = the rock's top must be at least { $gap } m below the surface
boids-obstacle-pillar-not-a-number = the pillar's position must be numbers
boids-obstacle-corners = a polygon needs { $min } to { $max } corners (got { $count })
boids-obstacle-corner-not-a-number = every corner must be a pair of numbers
boids-obstacle-corners-too-close = corners { $first } and { $second } are closer than { $min } m
boids-obstacle-flat = the polygon is flat: its area is below { $min } m²
boids-obstacle-not-convex = the polygon must be convex (it bends inwards at corner { $corner })
boids-obstacle-no-such = there is no obstacle number { $index } (there are { $count })
boids-obstacle-place-not-a-number = the new place must be a pair of numbers
boids-obstacle-too-close = it is too close to obstacle { $other }: keep at least { $gap } m between them
