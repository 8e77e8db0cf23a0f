# Por qué una roca, un pilar o una repisa de arrecife no puede ir donde se
# puso o se movió (src/sim/common/obstacle.rs, src/sim/boids/placement.rs).

boids-obstacle-radius = el radio debe estar entre { $min } m y { $max } m (se pidió { $radius } m)
boids-obstacle-near-the-glass = debe quedar al menos a { $gap } m del vidrio (está en ({ $x }; { $z }) m)
boids-obstacle-height-not-a-number = su posición y su altura deben ser números
boids-obstacle-off-the-sand = debe apoyarse en la arena (base en y = { $floor } m; se pidió { $base } m)
boids-obstacle-height = su altura debe ser mayor que 0 m y su parte de arriba debe quedar al menos { $gap } m bajo la superficie (altura { $height } m)
boids-obstacle-rock-not-a-number = la posición de la roca debe darse con números
boids-obstacle-rock-buried = la roca está enterrada en la arena: sube su centro
boids-obstacle-rock-floats = la roca flota: debe tocar la arena
boids-obstacle-rock-too-high = la parte de arriba de la roca debe quedar al menos { $gap } m bajo la superficie
boids-obstacle-pillar-not-a-number = la posición del pilar debe darse con números
boids-obstacle-corners = un polígono necesita de { $min } a { $max } esquinas (tiene { $count })
boids-obstacle-corner-not-a-number = cada esquina debe ser un par de números
boids-obstacle-corners-too-close = las esquinas { $first } y { $second } están a menos de { $min } m una de otra
boids-obstacle-flat = el polígono es plano: su área es menor que { $min } m²
boids-obstacle-not-convex = el polígono debe ser convexo (se dobla hacia adentro en la esquina { $corner })
boids-obstacle-no-such = no hay ningún obstáculo número { $index } (hay { $count })
boids-obstacle-place-not-a-number = el nuevo lugar debe ser un par de números
boids-obstacle-too-close = está demasiado cerca del obstáculo { $other }: deja al menos { $gap } m entre los dos
