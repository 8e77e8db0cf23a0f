# Las palabras del laboratorio de aprendizaje (src/ui/learning_panel.rs,
# src/sim/learning/*.rs) y las negativas del laboratorio (src/lab.rs).

## Los controles.
learning-heading = Aprender a nadar
learning-learner = Aprendiz
    .help = Quién aprende. Un tiburón tiene el mismo cuerpo, pero el doble de largo
learning-fish = Pez
learning-shark = Tiburón
learning-train-start = Empezar a entrenar
    .help = El pez practica un poco en cada cuadro: cambia al azar el ritmo de sus músculos, se queda con los cambios que lo llevan más lejos y a veces se queda con uno peor para explorar (recocido simulado)
learning-train-pause = Pausar el entrenamiento
learning-reset = Reiniciar el entrenamiento
    .help = Borra todo lo aprendido: el pez vuelve a no saber nadar, como si no tuviera cerebro
learning-swimmer-uses = El nadador entre las boyas usa
    .help = Qué controladores hacen nadar al pez entre las dos boyas naranjas: los ajustados a mano que escribieron sus diseñadores, o los que aprendió por sí mismo
learning-learned = Aprendidos
learning-hand-tuned = Ajustados a mano
learning-race = Empezar la carrera
    .help = Copias del pez, guardadas después de más y más intentos del primer ejercicio, compiten desde la misma línea de salida (la Fig. 7 del artículo). Practicar ayuda mucho al principio y luego casi nada: las dos últimas copias llegan casi juntas
learning-save = Guardar controladores
    .help = Descarga como archivo lo que aprendió el pez
learning-load = Cargar controladores
    .help = Abre un archivo guardado antes; después el nadador lo usa

## Los ejercicios.
learning-drill-swim-far = nadar lo más lejos que pueda
learning-drill-hold-speed = nadar en línea recta a { $speed } largos de cuerpo/s
learning-drill-turn-left = girar a la izquierda a { $rate }°/s
learning-drill-turn-right = girar a la derecha a { $rate }°/s

## El progreso bajo el tanque.
learning-drill-title = Ejercicio { $number } de { $count }: { $drill }
learning-all-drills = { $count ->
    [one] El ejercicio está aprendido
   *[other] Los { $count } ejercicios están aprendidos
}
learning-tries = { $tries } de { $total } intentos · mejor E { $best } · temperatura { $temperature }
    .help = E es lo que el pez intenta hacer pequeño: qué tan lejos terminó de su meta, más un poco por los músculos bruscos. La temperatura es cuántas ganas tiene todavía de probar movimientos peores; se enfría a medida que avanza el entrenamiento
learning-in-use = Controladores aprendidos en uso: { $source }
learning-source-shipped = el conjunto incluido (entrenado antes)
learning-source-here = entrenados aquí
learning-source-loaded = cargados desde un archivo
learning-swimmer-on-its-way = Nadador: en camino a la primera boya
learning-swimmer-first-buoy = Nadador: primera boya a los { $first } s
learning-swimmer-buoys = Nadador: boyas a los { $first } s y a los { $second } s
learning-race-after = Carrera después de { $seconds } s (la Fig. 7 del artículo):
learning-race-racer = competidor
learning-race-practice = práctica (intentos)
learning-race-distance = distancia
learning-race-metres = { $distance } m
learning-race-what = Después de unos miles de intentos, las copias nadan casi igual de rápido. La carrera muestra que los primeros minutos de práctica son los que más cuentan y que después la mejora casi se detiene; por eso la copia que practicó más no siempre gana.

## Las gráficas.
learning-objective-caption = Qué tan bien nada (E, menor es mejor)
    .help = Cuánto se alejó el nado de práctica de su meta (el blanco, la rapidez o el giro del ejercicio), más un poco por los músculos bruscos, como una puntuación E: menor es mejor. Alta al principio: el pez se agita sin avanzar; bajando: está aprendiendo; plana y baja: ya aprendió a nadar (la línea de lo mejor nunca sube).
learning-axis-tries = intentos
learning-line-now = ahora
learning-line-best = mejor
learning-muscle-middle = medio
learning-muscle-tail = cola
learning-fig8-raw = Lo que aprendió (músculos izquierdos)
    .help = Qué tan fuerte tira cada músculo durante el nado de práctica, tal como lo aprendió. Ondas altas y regulares: una brazada fuerte y pareja; líneas planas: músculos que el pez casi no usa.
learning-fig8-modes = Ritmos principales (modos de Fourier)
    .help = Solo el ritmo principal: la onda más fuerte del patrón aprendido, alrededor del tirón promedio de cada músculo. Oscilaciones grandes y parejas: un solo ritmo lleva casi toda la brazada; si se parece mucho al primer gráfico, no hace falta mucho más.
learning-fig8-abstract = Controlador simplificado
    .help = El patrón aprendido reconstruido con esas pocas ondas (la abstracción de Fourier): esto es lo que el pez conserva. Cuanto más se parece al primer gráfico, menos perdió el pez al quedarse solo con unas pocas ondas.
learning-axis-time = tiempo (s)

## Avisos.
learning-open-first = Primero abre el laboratorio de aprendizaje.
learning-open-first-reason = primero abre el laboratorio de aprendizaje
learning-no-race = Todavía no hay carrera: { $reason }.
learning-loaded = Controladores cargados: ahora el nadador los usa.
learning-load-refused = Ese archivo no se puede usar; no se cambió nada: { $reason }
learning-save-failed = no se pudieron escribir los controladores: { $reason }
learning-race-not-ready = la carrera necesita que termine el primer ejercicio ({ $done } de { $needed } pasos de recocido simulado hechos)

## Por qué no se puede usar un archivo de controladores.
learning-map-no-straight = no se aprendió ningún controlador para nadar en línea recta que haga avanzar al pez
learning-map-invalid = un controlador aprendido contiene un número no finito o demasiados modos
learning-set-too-large = el archivo pesa más de { $max } bytes
learning-set-not-a-set = el archivo no es un conjunto de controladores aprendidos: { $reason }
learning-set-wrong-version = el archivo tiene la versión de formato { $found }; este Shoal lee la versión { $expected }
learning-set-bad-controls = ejercicio { $drill }: los controles aprendidos están dañados (tamaño incorrecto, o un valor fuera del rango de 0 a 1 o que no es un número)
learning-set-bad-controller = ejercicio { $drill }: el controlador abstraído está dañado (un valor que no es un número, o más de { $max } modos)
learning-set-non-finite = ejercicio { $drill }: una velocidad, un giro o un objetivo medido no es un número
learning-set-map = el conjunto no puede hacer nadar a un pez: { $reason }

## Las negativas del laboratorio (src/lab.rs): órdenes de la API shoal.* y de los paneles.
lab-error-learning-lab-only = { $command }() solo funciona en el laboratorio de aprendizaje
lab-error-physics-scene-only = turn() solo funciona en la escena de los peces físicos
lab-error-no-fish-selected = turn(): primero selecciona un pez (physics.selected)
lab-error-turn-out-of-range = turn(): { $angle } está fuera de rango: elige de -{ $max } a { $max } grados
lab-error-no-moment = skip(): esta escena no tiene un momento al que saltar (las demostraciones del arrecife sí lo tienen)
