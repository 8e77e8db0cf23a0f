# El arrecife: sus animales, su registro de sucesos (src/sim/reef/) y sus paneles (src/ui/reef_*.rs).

reef-animal = { $kind ->
    [shark] tiburón { $index }
    [fish] pez { $index }
   *[pacifist] pacífico { $index }
}

## El registro de sucesos (src/sim/reef/events.rs y las etapas que registran).

event-fled = { $fish } huyó de { $predator }
event-ate = { $predator } se comió a { $prey }
event-ate-plankton = { $fish } comió plancton (hambre { $before } → { $after })
event-missed = { $predator } no atrapó a { $prey }: { $crowd ->
    [one] otra presa cercana lo confundió
   *[other] otras { $crowd } presas cercanas lo confundieron
}
event-chose = { $female } eligió a { $male } ({ $male_length } m de largo) en vez de a { $over } ({ $over_length } m): { $why ->
    [bigger] ella prefiere los machos más grandes
   *[nearer] ella compara el tamaño con la distancia, y el más grande estaba más lejos
}
event-left-for-larger = { $female } dejó a { $old } por { $new }, más grande
event-began-courting = { $male } y { $female } empezaron el cortejo: giros en lazo
event-courtship-phase = { $male } y { $female } empezaron { $phase ->
    [circling] a dar vueltas
    [ascending] el ascenso para desovar
    [nuzzling] a rozarse
    [spawned] a desovar
   *[looping] los giros en lazo
}
event-spawned = { $male } y { $female } desovaron
event-stopped-courting = { $male } y { $female } dejaron el cortejo
event-school-split = El banco de peces se dividió en { $groups } grupos
event-school-split-at-pillar = El banco de peces se dividió en { $groups } grupos junto al pilar
event-school-joined = El banco de peces volvió a unirse
event-school-at-pillar = El banco de peces llegó al pilar
event-school-passed-whole = El banco de peces entero pasó por un solo lado del pilar
