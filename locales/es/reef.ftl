# El arrecife: sus animales, su registro de sucesos (src/sim/reef/) y sus paneles (src/ui/reef_*.rs).

reef-animal = { $kind ->
    [shark] tiburón { $index }
    [fish] pez { $index }
   *[pacifist] pacífico { $index }
}

## El registro de sucesos (src/sim/reef/events.rs y las etapas que registran).

reef-event-fled = { $fish } huyó de { $predator }
reef-event-ate = { $predator } se comió a { $prey }
reef-event-ate-plankton = { $fish } comió plancton (hambre { $before } → { $after })
reef-event-missed = { $predator } no atrapó a { $prey }: { $crowd ->
    [one] otra presa cercana lo confundió
   *[other] otras { $crowd } presas cercanas lo confundieron
}
reef-event-chose = { $female } eligió a { $male } ({ $male_length } m de largo) en vez de a { $over } ({ $over_length } m): { $why ->
    [bigger] ella prefiere los machos más grandes
   *[nearer] ella compara el tamaño con la distancia, y el más grande estaba más lejos
}
reef-event-left-for-larger = { $female } dejó a { $old } por { $new }, más grande
reef-event-began-courting = { $male } y { $female } empezaron el cortejo: giros en lazo
reef-event-courtship-phase = { $male } y { $female } empezaron { $phase ->
    [circling] a dar vueltas
    [ascending] el ascenso para desovar
    [nuzzling] a rozarse
    [spawned] a desovar
   *[looping] los giros en lazo
}
reef-event-spawned = { $male } y { $female } desovaron
reef-event-stopped-courting = { $male } y { $female } dejaron el cortejo
reef-event-school-split = El banco de peces se dividió en { $groups } grupos
reef-event-school-split-at-pillar = El banco de peces se dividió en { $groups } grupos junto al pilar
reef-event-school-joined = El banco de peces volvió a unirse
reef-event-school-at-pillar = El banco de peces llegó al pilar
reef-event-school-passed-whole = El banco de peces entero pasó por un solo lado del pilar

## El panel del arrecife (src/ui/reef_panel.rs).

reef-intention-avoid = algo le estorba el paso: se desvía
    .word = esquivar
reef-intention-escape = hay un depredador cerca: huye
    .word = huir
reef-intention-school = nada con los demás de su especie
    .word = nadar en banco
reef-intention-eat = tiene hambre: busca comida
    .word = comer
reef-intention-mate = quiere aparearse: corteja
    .word = aparearse
reef-intention-leave = no le gusta el agua de aquí: se va
    .word = irse
reef-intention-wander = todo está bien: pasea
    .word = pasear
reef-heading = Arrecife
reef-body = Cuerpo
    .help = Músculos: cada pez es un cuerpo de resortes que nada doblándose (más lento de calcular, fiel al artículo). Puntos: cada pez es un punto que se dirige directamente (rápido, para escenas grandes). La mente es la misma.
reef-body-muscles = Músculos
reef-body-points = Puntos
reef-show-water = Mostrar el agua
    .help = Colorea el agua según lo clara o lo cálida que está. A algunos peces les gusta la luz o el calor y se van del agua que no les gusta
reef-show-vision = Mostrar lo que ve el pez seleccionado
    .help = Un pez ve todo a su alrededor excepto un cono ciego estrecho detrás, hasta donde el agua es clara. La línea de color apunta a aquello en lo que está pensando
reef-name-tags = Etiquetas con nombre
    .help = Escribe sobre cada animal su nombre, como lo llama el registro de sucesos ("tiburón 10", "pez 5"): haz clic en una línea del registro para seguir a ese pez
reef-follow = La cámara lo sigue
    .help = Mantén al pez seleccionado en el centro de la vista
reef-deselect = Soltar
    .help = Deja de seleccionar al pez
reef-animal-number = animal { $index }
reef-selected = Seleccionado: { $name } (abajo se muestra su mente)
reef-select-hint = Haz clic en un pez del tanque para mirar dentro de su cabeza.

## Las demostraciones (src/sim/reef/demos.rs): nombre, una frase y el momento que busca *Saltar*.

reef-demo-reef = Arrecife
    .help = Un arrecife completo: los peces comen plancton, un tiburón caza un banco de peces, las parejas se cortejan.
    .moment = la próxima captura o el próximo desove
reef-demo-predator-and-school = Depredador y banco de peces
    .help = Un tiburón hambriento y un banco de presas: ¿a quién atrapa?
    .moment = la próxima captura del tiburón
reef-demo-courtship = Cortejo
    .help = Dos machos cortejan a una hembra; ella prefiere al más grande.
    .moment = el desove
reef-demo-feeding = Alimentación
    .help = Peces hambrientos encuentran plancton y lo succionan.
    .moment = el próximo bocado
reef-demo-school-meets-obstacle = El banco y el obstáculo
    .help = Un banco de peces se topa con un pilar: ¿se divide para rodearlo y luego vuelve a unirse?
    .moment = lo que hará el banco de peces

## Saltar al momento (src/ui/reef_skip.rs); $time es el tiempo simulado como "1:05".

reef-skip = Saltar hasta { $what } »
    .help = Avanza tan rápido como pueda esta computadora hasta que ocurra, y luego retrocede unos segundos para que puedas verlo. Es la misma simulación: saltar solo cambia cuándo lo ves
reef-skip-looked = se buscó { $time } hacia adelante
reef-skip-cancel = Cancelar
reef-skip-banner = Buscando { $what } más adelante… { $time }
reef-skip-found = Se avanzó hasta { $time }. Mira: en unos { $seconds } s el registro dirá “{ $line }”.
reef-skip-not-found = No se encontró { $what } en los próximos { $time } de esta simulación: sigue desde ahí. Prueba otra semilla.

## Mentes (src/ui/reef_minds.rs).

reef-minds = Mentes
    .help = Qué tan rápido le da hambre o ganas de aparearse a cada tipo de pez, a qué distancia lo asusta un tiburón, y su carácter. Los cambios se aplican de inmediato.
reef-minds-sharks = Tiburones
    .help = Los cazadores: se comen a los peces presa
reef-minds-prey = Peces presa
    .help = Peces pequeños que forman un banco y huyen del tiburón
reef-minds-pacifists = Pacíficos
    .help = Peces que comen plancton y se cortejan
reef-minds-none-here = No hay ninguno en esta demostración
reef-minds-no-fish = No hay peces en este arrecife.
reef-minds-reset = Los valores de la demostración
    .help = Deshaz todos los cambios a este tipo de pez

## Dibujado sobre el tanque (src/ui/reef_overlay.rs).

reef-her-choice = su elección

## El inspector bajo el tanque (src/ui/reef_inspector.rs).

reef-tab-mind = Mente
reef-tab-history = Últimos 2 min
reef-tab-sees = Lo que ve
reef-tab-log = Sucesos
reef-summary = { $animals ->
    [one] { $animals } animal vivo
   *[other] { $animals } animales vivos
} · { $plankton ->
    [one] { $plankton } partícula de plancton
   *[other] { $plankton } partículas de plancton
} · { $eaten ->
    [one] { $eaten } presa comida
   *[other] { $eaten } presas comidas
} · { $spawnings ->
    [one] { $spawnings } desove
   *[other] { $spawnings } desoves
}
reef-summary-hint = Haz clic en un pez para ver su hambre, su miedo y sus planes, y lo que ve.
reef-sees = Lo que ve
    .help = El mundo a través del ojo de este pez: ve casi todo a su alrededor, comprimido en un círculo. Su cerebro solo usa cuánta luz hay
reef-brightness = Brillo { $value }
reef-water = Agua a { $value } °C
# $sex: male, female; $kind: predator, prey, pacifist.
reef-inspector-title = { $name } · { $kind ->
    [predator] depredador
    [prey] presa
   *[pacifist] pacífico
} { $sex ->
    [male] macho
   *[female] hembra
}
reef-inspector-eaten = { $name } · devorado
# $light: bright, dim, any; $temperature: warm, cool, any; $schools: yes, no.
reef-inspector-habits = Especie { $species } · { $length } m · le gusta la luz { $light ->
    [bright] intensa
    [dim] tenue
   *[any] de cualquier intensidad
} y el agua { $temperature ->
    [warm] cálida
    [cool] fresca
   *[any] a cualquier temperatura
}{ $schools ->
    [yes] {" · forma bancos"}
   *[no] {""}
}
    .help = Hábitos: lo que a este pez le gusta desde que nació. Nunca cambian.
reef-inspector-hunger = Hambre
    .help = Crece mientras digiere la comida; baja cuando come. Cerca de 1: el pez tiene mucha hambre y va a buscar comida; cerca de 0: acaba de comer.
    .plot = hambre
reef-inspector-libido = Libido
    .help = Crece con el tiempo desde que se apareó, salvo si tiene hambre. Cerca de 1: busca pareja y la corteja; cerca de 0: acaba de desovar (o tiene demasiada hambre para eso).
    .plot = libido
reef-inspector-fear = Miedo
    .help = Es alto cuando ve un depredador cerca. Cerca de 1: hay un tiburón cerca y el pez huye (o se esconde en su cardumen); cerca de 0: no ve ningún depredador.
    .plot = miedo
reef-intention-hunt = tiene hambre: caza
reef-inspector-intends = Quiere { $intention }: { $sentence }
reef-inspector-focus = Se fija en: { $target }
reef-inspector-remembers = Recuerda: { $intention }, { $target } (lo retoma después de esquivar)
reef-inspector-remembers-nothing = Recuerda: nada
reef-inspector-courting = Cortejo: { $phase ->
    [circling] vueltas
    [ascending] ascenso para desovar
    [nuzzling] roces
    [spawned] desove
   *[looping] giros en lazo
} con { $partner } ({ $count })
# $fins: grados con su signo ("+12").
reef-inspector-muscles = Músculos: nada al { $speed } %{ $turning ->
    [yes] {", girando"}
   *[no] {""}
}, aletas { $fins }°
    .help = Lo que el cerebro les dice a los músculos en este momento
reef-inspector-speed = Velocidad { $speed } m/s (cuerpo de punto)
reef-target-nothing = nada en particular
reef-target-plankton = plancton { $id }
reef-target-rock = roca { $id }
reef-target-glass = el vidrio
reef-inspector-history = Su mente en los últimos dos minutos
reef-log = Qué pasó
    .help = Lo más reciente primero: comidas, persecuciones, cortejos. Haz clic en una línea para seguir a quien lo hizo
reef-log-empty = Nada todavía.
reef-log-follow = Haz clic para seleccionar y seguir a { $who }
