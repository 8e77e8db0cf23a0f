# Las palabras de los ajustes (src/settings/*.rs, src/ui/setting_slider.rs,
# src/ui/tank_panel.rs). El mensaje de cada ajuste numérico es
# setting-<sección>-<clave>: la etiqueta, con .help (ayuda al pasar el ratón),
# .field (ayuda propia de un campo), .fewer y .more (los botones − y + de una
# cantidad); un valor con nombre es setting-<sección>-<clave>-<nombre> con .help.

## Unidades que siguen a un número (con su espacio).
setting-unit-metres = {" "}m
setting-unit-metres-per-second = {" "}m/s
setting-unit-metres-per-second-squared = {" "}m/s²
setting-unit-degrees = °
setting-unit-times = ×
setting-unit-food = {" "}de alimento
setting-unit-body-lengths = {" "}LC

## Los controles de una fila.
setting-count-fewer = { $label }: menos
setting-count-more = { $label }: más
setting-named-value = { $name }: { $help }
    .name = { $setting }: { $name }

## Por qué se rechazó un ajuste.
setting-error = ajuste '{ $key }': { $reason }
setting-error-out-of-range = { $value } está fuera del rango: elige entre { $min } y { $max }
setting-error-selected-fish = { $selected } está fuera del rango: hay { $count } peces (de 0 a { $last }), o null para ninguno
setting-error-selected-animal = { $selected } está fuera del rango: hay { $count } animales (de 0 a { $last }), o null para ninguno
setting-error-needs-selected-fish = necesita un pez seleccionado: indica también selected
setting-error-too-many-obstacles = { $count } obstáculos son demasiados: como máximo { $max }
setting-error-not-an-object = set() recibe un objeto como {"{"}"speed": 2{"}"}, no { $value }
setting-error-unknown-key = ajuste desconocido '{ $key }'; los ajustes son: { $known }
setting-error-wrong-type = { $value } es del tipo equivocado ({ $hint })

## Por qué no se pudo abrir un enlace compartido.
setting-link-too-long = el enlace es demasiado largo ({ $count } caracteres) para ser un enlace de Shoal
setting-link-unknown-version = el enlace no empieza con una etiqueta de versión de Shoal ('{ $tag }')
setting-link-not-base64 = el enlace está dañado (no es texto base64 válido): tal vez se cortó al copiarlo
setting-link-not-deflate = el enlace está dañado (sus datos no se pueden descomprimir): tal vez se cortó al copiarlo
setting-link-not-json = los datos del enlace no son un texto de ajustes válido
setting-link-invalid = el enlace pide algo que Shoal no puede hacer: { $reason }
setting-link-sealed-damaged = los valores misteriosos del enlace están dañados ({ $why }): tal vez el enlace se cortó o se editó al copiarlo
setting-link-sealed-not-base64 = no son texto base64 válido
setting-link-sealed-short = son demasiado cortos
setting-link-sealed-checksum = al descifrarlos no dan lo que puso el maestro
setting-link-sealed-mismatch = no corresponden a los controles que el estudio convierte en misterio

## Los ajustes de toda la aplicación.
setting-app-speed = Velocidad
    .help = Qué tan rápido corre el tiempo: 1× es tiempo real, 2× es el doble de rápido
setting-app-seed = Semilla
    .help = El número que decide dónde empieza todo. La misma semilla siempre da la misma simulación, así que una clase puede compartirla
    .field = Escribe un número para empezar una simulación nueva a partir de él

## Los ajustes de un tanque de boids (laboratorio de cardúmenes, acuario).
setting-tank-containment = Contención
    .help = Con cuánta fuerza un pez se queda en el estanque: regresa hacia el agua abierta antes de que su camino se acerque al vidrio, la arena o la superficie, y junto a ellos gira a lo largo en vez de chocar. En 0 hasta un cardumen nada pegado al vidrio.
setting-tank-alignment = Alineación
    .help = Cuánto copia un pez la dirección en la que nadan sus vecinos (los vecinos cercanos cuentan más: su rumbo se ve mejor; ver Vista clara).
setting-tank-cohesion = Cohesión
    .help = Cuánto nada un pez hacia el centro de los vecinos que puede ver (y de los peces lejanos que ve; ver Peces lejanos), frenando al llegar.
setting-tank-separation = Separación
    .help = Cuánto cuida un pez su propio espacio: se aleja de los peces que entran en su espacio personal, más fuerte cuanto más cerca están. Una separación fuerte también hace más lento al cardumen: dentro de un cardumen los empujones llegan de todos lados y casi se anulan, pero cada uno frena un poco al pez (el cardumen de Grupo nada a unos 0,29 m/s con separación 25 y a 0,18 m/s con 100).
setting-tank-avoidance = Evasión
    .help = Con cuánta fuerza un pez esquiva los obstáculos: las rocas, los pilares, las repisas, las rayas y los peces que vienen directo hacia él (tres o más juntos cuentan como un solo obstáculo). El vidrio, la arena y la superficie son tarea de la contención.
setting-tank-vision-distance-m = Distancia de visión
    .help = Hasta qué distancia puede ver un pez a sus vecinos, en metros.
setting-tank-vision-angle-deg = Ángulo de visión
    .help = Qué tan amplio ve un pez a su alrededor. A 360° ve también detrás; a 300° tiene un punto ciego detrás de la cola.
setting-tank-max-speed-m-per-s = Velocidad máxima
    .help = Lo más rápido que puede nadar un pez, en metros por segundo.
setting-tank-max-force-m-per-s2 = Fuerza de giro
    .help = Con cuánta fuerza puede un pez girar o acelerar de golpe (la fuerza máxima). Los valores pequeños dan giros lentos y perezosos.
setting-tank-personal-space-m = Espacio personal
    .help = Qué tan cerca puede llegar otro pez antes de que la separación aleje a este. Un cardumen se acomoda a más o menos un largo de cuerpo (aquí 0,3–0,5 m).
setting-tank-wander = Deambular
    .help = Cuánto anda un pez de aquí para allá por su cuenta, de 0 a 100 (en la escala de los impulsos). Es igual para solitarios y cardúmenes: la alineación y la cohesión de un cardumen lo vencen, las de los solitarios no.
setting-tank-clear-sight-m = Vista clara
    .help = Hasta esta distancia un pez ve bien hacia dónde nada un vecino; un pez al doble de distancia cuenta la mitad en la alineación, porque se ve más pequeño. En 0 un pez no ve hacia dónde nada ningún vecino y la alineación no tiene nada que copiar. Es igual para solitarios y cardúmenes: los solitarios se mantienen más lejos, así que se copian menos.
setting-tank-distant-pull = Peces lejanos
    .help = Cuánto nada un pez hacia los peces que ve lejos, como porcentaje de lo que lo atraen sus vecinos cercanos. Es parte de la cohesión, así que no hace nada cuando la cohesión es 0. Permite que dos cardúmenes que se ven se junten; en 0 solo atraen los vecinos cercanos.
setting-tank-min-speed-m-per-s = Velocidad mínima
    .help = La velocidad por debajo de la cual un pez nunca baja, en metros por segundo: los peces siguen nadando aunque sus impulsos se anulen. Un cardumen apretado suele nadar cerca de esta velocidad.
setting-tank-fish-count = Peces
    .help = Cuántos peces (las presas) hay en el tanque.
    .fewer = Quitar 10
    .more = Agregar 10
    .few = Con 50 peces o menos los ajustes se diferencian menos: los peces Individuales se encuentran poco, pero cuando dos se encuentran, su poco de alineación los mantiene nadando uno al lado del otro. En 20 peceras de 20 peces, la polarización de los solitarios fue de cerca de 0,4 (hasta 0,68 en una pecera), cuando los rumbos al azar dan cerca de 0,2.
    .crowded = Con 1000 peces o más la pecera está llena: los peces Individuales se empujan entre sí con más fuerza de la que la contención los retiene, así que llenan la pecera hasta el vidrio (con 2000 peces cerca de un tercio lo toca). Un cardumen de Grupo se alinea menos (polarización de 0,6 a 0,7 con 1000 peces, de 0,3 a 0,5 con 2000) y tampoco forma un solo anillo que gira.
setting-tank-sharks = Tiburones
    .help = Cazadores. Un tiburón persigue a un pez; los peces que lo ven huyen y se juntan (mientras huye, el peso de cohesión de un pez cuenta el doble y el de separación la mitad).
    .fewer = Quitar 1
    .more = Agregar 1
setting-tank-stingrays = Rayas
    .help = Peces planos que se deslizan sobre la arena. Los otros peces nadan alrededor de ellas como si fueran rocas.
    .fewer = Quitar 1
    .more = Agregar 1
setting-aquarium-fish-count = Peces
    .help = Cuántos peces hay en el tanque

## Los ajustes predefinidos de un tanque.
setting-preset-individual = Individual (solitario)
    .help = Peces a los que les gusta estar solos: guardan su distancia y no intentan mantenerse juntos.
setting-preset-group = Grupo (cardumen)
    .help = Peces que viven en cardumen: se mantienen cerca, nadan en la misma dirección y aun así nunca chocan.
setting-preset-monte-carlo-paper = Monte Carlo (artículo)
    .help = El modo de lotería con las probabilidades publicadas en el artículo: en cada momento gana un impulso.
    .note = En el sorteo del artículo la cohesión gana el 41 % de las veces y la separación solo el 12,5 %, así que los peces se aprietan más que con los otros ajustes: los vecinos más cercanos quedan a medio largo de cuerpo y los cuerpos a menudo se superponen (en el 41 % de las muestras un pez tenía un vecino a menos de medio largo; 20 peceras de 200 peces).
setting-preset-custom = Personalizado
    .help = Tu propia mezcla: mueve cualquier control deslizante y el ajuste pasa a ser Personalizado.

## Los modos de control de un tanque.
setting-mode-blended = Mezcla (directo)
setting-mode-classic = Clásico
setting-mode-direct-alternate = Alternancia directa
setting-mode-monte-carlo = Monte Carlo

## Los controles de un tanque (src/ui/tank_panel.rs).
setting-tank-panel-preset = Ajuste predefinido
    .help = Mezclas ya hechas de los cinco impulsos, de la Tabla 1 del artículo
setting-tank-panel-mode = Cómo se combinan los impulsos
    .help = El modo de control: cómo convierte un pez cinco impulsos en un solo movimiento
    .block = modo de control
setting-tank-panel-mode-note = Deambular y huir de los tiburones no son impulsos del modo: actúan por encima de él, en todos los modos.
setting-tank-panel-urges = Impulsos (0–100)
    .help = Cuánto cuenta cada impulso, en la escala de 0 a 100 del artículo
setting-tank-panel-senses = Sentidos, cuerpo y deambular
    .help = No forman parte de los ajustes predefinidos: Individual y Grupo cambian solo los cinco impulsos, así que estos siguen iguales cuando eliges uno.
setting-tank-panel-animals = Animales

## Los ajustes de los peces físicos.
setting-physics-fish-count = Peces
    .help = Cuántos peces movidos por músculos nadan en el tanque. Cada uno tiene 23 masas unidas por 91 resortes
setting-physics-sharks = Tiburones
    .help = Los tiburones están hechos como los peces, solo que el doble de largos y cuatro veces más pesados
    .fewer = Un tiburón menos
    .more = Un tiburón más
setting-physics-current-m-per-s = Corriente
    .help = Qué tan rápido fluye el agua alrededor del tanque. Un pez que deja de nadar se deja llevar; para quedarse quieto tiene que nadar en contra
setting-physics-hand-speed = Nadar
    .help = Con cuánta fuerza baten los músculos de la cola: 0 descansa, 1 es el nado más rápido
setting-physics-hand-pitch-deg = Aletas
    .help = Inclina las aletas laterales: hacia arriba el pez sube, hacia abajo se sumerge (solo mientras nada)
setting-physics-turn-angle-deg = Giro
    .help = El giro que pide el botón: positivo hacia la izquierda del pez, negativo hacia su derecha. Los giros de más de 90° se hacen con giros más pequeños

## Los ajustes del arrecife.
setting-reef-prey-count = Peces presa
    .help = Cuántos peces presa pequeños viven en este arrecife (forman cardumen y huyen del tiburón)
setting-reef-food-count = Plancton
    .help = Cuánto plancton flota en el agua; el plancton que se comen se repone
setting-reef-visibility-m = Visibilidad
    .help = Hasta dónde puede ver un pez en esta agua, en metros. Agua turbia: los peces ven menos, encuentran menos comida y notan al tiburón más tarde
setting-reef-current-m-per-s = Corriente
    .help = Qué tan rápido fluye el agua; arrastra el plancton y mece las algas
setting-reef-overlay-none = Nada
setting-reef-overlay-light = Luz
setting-reef-overlay-temperature = Temperatura

## La mente de un pez del arrecife (reef.traits.<tipo>.<rasgo>).
setting-minds-digestion-rate-per-unit = El hambre crece (p0)
    .help = p0: qué tan rápido se digiere una comida, o sea, qué tan pronto vuelve a tener hambre el pez, por unidad de tiempo de 1/40 s. Tranquilo (el valor de Shoal) 0,0003: vuelve a tener hambre 21 s después de comer hasta llenarse. El nominal del artículo, 0,00067: después de 9 s; voraz 0,005: después de 1 s
setting-minds-digestion-rate-per-unit-calm = Tranquilo
    .help = p0 = 0,0003 (el valor de Shoal)
setting-minds-digestion-rate-per-unit-nominal = Nominal
    .help = p0 = 0,00067 (el del artículo)
setting-minds-digestion-rate-per-unit-ravenous = Voraz
    .help = p0 = 0,005 (el del artículo)
setting-minds-libido-rate-per-unit = La libido crece (p1)
    .help = p1: qué tan rápido crece el deseo de aparearse después de aparearse, por unidad de tiempo de 1/40 s. Tranquilo (el valor de Shoal) 0,0011: un pez alimentado quiere aparearse otra vez 6 s después. El nominal del artículo, 0,0025: después de 2,5 s; manía sexual 0,01: después de 0,6 s
setting-minds-libido-rate-per-unit-calm = Tranquilo
    .help = p1 = 0,0011 (el valor de Shoal)
setting-minds-libido-rate-per-unit-nominal = Nominal
    .help = p1 = 0,0025 (el del artículo)
setting-minds-libido-rate-per-unit-sexual-mania = Manía sexual
    .help = p1 = 0,01 (el del artículo)
setting-minds-appetite-food-units = Apetito (α)
    .help = α: cuánta comida llena al pez (una partícula de plancton es 1, un pez presa 4)
setting-minds-fear-distance-body-lengths = Distancia de miedo (D0)
    .help = D0: un tiburón más cerca que esta cantidad de largos de cuerpo asusta al pez todo lo que puede asustarse (artículo: 3,85)
setting-minds-collision-box-ahead-body-lengths = Caja de choque
    .help = Hasta dónde mira el pez hacia adelante en busca de cosas en su camino
setting-minds-collision-box-ahead-body-lengths-timid = Tímido
    .help = esquiva cualquier cosa lejana por delante (1,5 largos de cuerpo)
setting-minds-collision-box-ahead-body-lengths-ordinary = Normal
    .help = esquiva lo que está a 0,8 largos de cuerpo por delante
setting-minds-collision-box-ahead-body-lengths-courageous = Valiente
    .help = esquiva solo en el último momento (0,3 largos de cuerpo)
setting-minds-persistence-body-lengths = Constancia
    .help = ¿El pez se queda con la comida, la presa o la pareja que eligió?
setting-minds-persistence-body-lengths-fickle = Inconstante
    .help = cambia a cualquier objetivo que esté un poco más cerca
setting-minds-persistence-body-lengths-ordinary = Normal
    .help = cambia cuando otro está 2 largos de cuerpo más cerca
setting-minds-persistence-body-lengths-devoted = Fiel
    .help = se queda con su objetivo a menos que otro esté 20 largos de cuerpo más cerca
setting-minds-fear-threshold = Alarma con miedo (f0)
    .help = f0: un miedo por encima de esto hace que el pez intente escapar (artículo: entre 0,1 y 0,5)
setting-minds-panic-threshold = Pánico con miedo (f1)
    .help = f1: cuando el tiburón más cercano lo asusta más que esto, un pez de cardumen deja el cardumen y huye solo
setting-minds-urge-threshold = Actúa por impulsos desde (r)
    .help = r: un hambre (o un deseo de aparearse) por encima de esto hace que el pez busque comida (o pareja) (artículo: menos de 0,5)

## Los ajustes del laboratorio de aprendizaje.
setting-learning-annealing-steps = Intentos por ejercicio
    .help = Cuántos intentos tiene el pez para cada ejercicio. Más intentos, mejor nado (el mejor tiburón del artículo tuvo 6840). Cambiarlo empieza de nuevo

## A setting named out of its panel (the Experiment window, the studio's
## rules): src/settings/names.rs.
setting-name-kind = { $kind } · { $label }
setting-name-unit = { $label } ({ $unit })
setting-name-left = { $label } (tanque izquierdo)
setting-name-right = { $label } (tanque derecho)
setting-name-left-unit = { $label } ({ $unit }, tanque izquierdo)
setting-name-right-unit = { $label } ({ $unit }, tanque derecho)
setting-name-selected = Pez seleccionado
setting-name-paused = Reproducir y pausar
setting-name-scene = Escena
setting-name-physics-behaviour = Cómo nadan los peces
setting-name-reef-demo = Demostración del arrecife
setting-name-learning-training = Entrenamiento
setting-name-learning-controller = Los controles del nadador
