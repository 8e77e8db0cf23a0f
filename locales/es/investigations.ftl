# Las investigaciones guiadas (src/investigation/, src/ui/investigation_panel.rs,
# src/ui/investigation_plot.rs): las palabras de las cinco investigaciones, los
# resultados de las ejecuciones, la ventana y el registro del estudiante.

## Las formas de curva que un estudiante puede dibujar.

inv-shape-flat = Plana: no cambia nada
inv-shape-line = Una línea recta hacia arriba
inv-shape-levels = Sube rápido y luego se estabiliza
inv-shape-peak = Sube y luego vuelve a bajar
inv-shape-down = Baja

## ¿Por qué los peces forman cardúmenes?

inv-why-school = ¿Por qué los peces forman cardúmenes?
    .teaser = Un tiburón caza peces solitarios en un tanque y un cardumen en el otro. ¿Quién pierde menos peces?
    .intro = Dos tanques con los mismos 40 peces y un tiburón cada uno. A la izquierda los peces son solitarios (los impulsos Individual); a la derecha forman un cardumen (los impulsos Grupo). Nada más cambia.
    .question = En 3 minutos, ¿qué tanque perderá menos peces ante su tiburón?
    .choice-loners = Los solitarios (tanque Individual)
    .choice-school = El cardumen (tanque Grupo)
    .choice-same = Más o menos igual
    .run-hint = Ejecutar vuelve a empezar los dos tanques desde el mismo inicio y cuenta durante 3 minutos simulados. Observa cada tiburón: ¿persigue a un pez hasta el final, o cambia de presa? Sube el control de Velocidad para llegar antes. La gráfica de esta ventana cuenta las capturas de cada tanque.
    .prompt-1 = Mira la gráfica de capturas de esta ventana. ¿Cuándo atrapó cada tiburón a sus peces: de forma constante o a rachas?
    .prompt-2 = Observa el tiburón cerca del cardumen (el tanque Grupo). ¿Qué le pasa al pez que estaba persiguiendo?
    .prompt-3 = ¿Por qué podría ser más difícil atrapar a un pez en medio de una multitud?
    .reveal = Muchos depredadores atrapan menos presas en un cardumen. Landeau y Terborgh (1986) dejaron que lobinas negras cazaran pececillos plateados: un pececillo solo era atrapado enseguida, pero frente a cardúmenes de 8 o más la lobina fallaba a menudo, porque cambiaba de objetivo una y otra vez. Es el efecto de confusión. Nuestro tiburón también lo tiene: cada segundo pierde de vista a su objetivo con una probabilidad que crece con el número de peces cercanos al objetivo, y necesita un segundo para elegir otro, así que nunca pierde a un pez solitario y a un pez de un cardumen apretado lo pierde casi enseguida. Los cardúmenes además ven antes al tiburón (muchos ojos) y reparten el riesgo; nuestro modelo tiene la confusión y la huida, pero no los muchos ojos. Una ejecución es una sola oportunidad: con las semillas 1 a 10 de este ajuste (en el navegador) los solitarios perdieron 78 peces y los cardúmenes 31; el cardumen perdió claramente menos en 8 de las 10 ejecuciones, los mismos en 1, y más en 1. Presiona Nueva junto a Semilla y vuelve a ejecutar para verlo. Ahora apaga la confusión: en el panel lateral, en Lo que agregamos a los artículos, desmarca Efecto de confusión, luego presiona Reiniciar y mira otros 3 minutos. Lo medimos en otras 8 semillas (41 a 48): con la confusión encendida, los solitarios perdieron 48 peces y los cardúmenes 24 (el cardumen perdió menos en 7 peceras de 8); con la confusión apagada, los solitarios perdieron 58 y los cardúmenes 55 (el cardumen perdió menos solo en 4 de 8). Sin la confusión, nuestro cardumen no está más seguro que los solitarios: un tiburón a su lado siempre tiene un pez a su alcance. El efecto de confusión es algo que agregamos al modelo; Reynolds y Tu y Terzopoulos no lo tienen.
    .reference = Landeau y Terborgh 1986, Anim. Behav. 34:1372; Lim y Tan, SIMBA (especies depredadoras); el tiburón de Shoal: docs/boids.md

## ¿Hay un líder?

inv-leader = ¿Hay un líder?
    .teaser = Un cardumen gira como uno solo. ¿Lo guía un pez?
    .intro = Un tanque con 60 peces en cardumen (los impulsos Grupo). Observa cómo el cardumen gira a la vez.
    .question = ¿Hay un pez que guía al cardumen?
    .choice-yes = Sí, un pez lo guía
    .choice-no = No, nadie lo guía
    .run-hint = Haz clic en peces (al menos uno) para ver a quién presta atención cada uno: los anillos blancos son los vecinos a los que reacciona. Luego apaga y enciende la alineación con los botones de abajo y observa la polarización (1: todos nadan en la misma dirección).
    .prompt-1 = ¿A qué vecinos prestaron atención los peces en los que hiciste clic? ¿Alguno de ellos era especial?
    .prompt-2 = ¿Qué le pasó al cardumen cuando la alineación estaba apagada?
    .prompt-3 = Entonces, ¿cómo puede un cardumen girar a la vez sin un líder?
    .reveal = Ningún pez guía. Cada pez reacciona solo a los pocos vecinos que ve (aquí sus 7 más cercanos, como hacen los estorninos: Ballerini et al. 2008), y el giro de todo el cardumen surge de estas reacciones locales. Pensar que una bandada o un cardumen debe tener un líder es una idea equivocada común (Resnick 1996). Al apagar la alineación los peces siguen juntos pero apuntan en todas direcciones: la polarización medida lo muestra. Los cardúmenes reales a veces sí siguen a individuos informados (Couzin et al. 2005: unos pocos peces que saben dónde hay comida pueden dirigir un cardumen sin que nadie los reconozca), pero ningún pez está al mando.
    .reference = Resnick 1996, Beyond the centralized mindset; Ballerini et al. 2008, PNAS 105:1232; Couzin et al. 2005, Nature 433:513

## ¿Qué impulso forma un cardumen?

inv-which-urge = ¿Qué impulso forma un cardumen?
    .teaser = Lleva el impulso de alineación de 0 a 100: ¿cómo cambia el orden del cardumen?
    .intro = Un tanque de peces en cardumen. El impulso de alineación hace que un pez nade en la dirección en que nadan sus vecinos. El experimento ejecuta el tanque con seis pesos de alineación, tres veces cada uno con semillas distintas, y mide la polarización (0: cada pez va por su lado, 1: todos en la misma dirección).
    .question = ¿Cómo cambia la polarización del cardumen cuando la alineación va de 0 a 100? Elige la forma.
    .x-label = peso de alineación
    .y-label = polarización
    .run-hint = El tanque sigue nadando mientras el experimento hace sus 18 ejecuciones en segundo plano. Mientras tanto, prueba tú mismo el control de alineación.
    .prompt-1 = ¿Dónde se aleja más tu dibujo de la curva medida?
    .prompt-2 = ¿Por qué un poco de alineación ya cambia tanto las cosas (o no)?
    .prompt-3 = ¿Basta la alineación sola para formar un cardumen? ¿Qué añadiría la cohesión?
    .reveal = En los modelos de este tipo (Vicsek et al. 1995; Couzin et al. 2002) el orden aparece de golpe: por debajo de cierta fuerza de alineación el grupo está desordenado, por encima los peces se alinean, como en una transición de fase (un cambio de estado repentino, como cuando el agua se congela). El nuestro mide cómo crece la polarización con el peso de alineación, con los demás impulsos fijos en los del ajuste Grupo: la barra de cada punto es un intervalo del 95 %: donde caería casi seguro el promedio de muchos más tanques, calculado a partir de tres tanques (tres son pocos, así que las barras son aproximadas: más o menos el rango de los tres). En nuestro tanque el orden llega rápido: de cerca de 0,2 sin alineación a cerca de 0,7 con un peso de 20, y se estabiliza cerca de 0,9 a partir de 40. La subida es menos brusca que una transición de libro de texto porque el tanque es pequeño (60 peces) y sus paredes hacen girar al cardumen una y otra vez.
    .reference = Vicsek et al. 1995, Phys. Rev. Lett. 75:1226; Couzin et al. 2002, J. Theor. Biol. 218:1; Lim y Tan, SIMBA (los cinco impulsos)

## ¿Cómo nada un pez?

inv-how-swim = ¿Cómo nada un pez?
    .teaser = Mueve la cola más rápido: ¿nada más rápido el pez, y sin límite?
    .intro = Un pez físico: 23 masas, 91 resortes, 12 de ellos músculos. Los músculos doblan el cuerpo de un lado a otro; el agua empuja la cola de vuelta y el pez avanza. El experimento mueve un cuerpo con toda su fuerza a siete frecuencias de coletazo y mide su velocidad.
    .question = ¿Cómo cambia la velocidad máxima del pez cuando su cola bate más rápido (de 1 a 5 coletazos por segundo)? Elige la forma.
    .x-label = coletazos por segundo (Hz)
    .y-label = velocidad (largos del cuerpo/s)
    .run-hint = La medición hace nadar un cuerpo aparte a cada frecuencia, un poco en cada fotograma. Mientras tanto, observa cómo los músculos del pez seleccionado se encienden en rojo cuando tiran.
    .prompt-1 = ¿Cuánto más lejos llega el pez por cada coletazo por segundo de más?
    .prompt-2 = ¿Qué pasó con el coletazo más rápido? Mira los músculos y la cola.
    .prompt-3 = ¿Por qué un pez no puede ir cada vez más rápido solo con mover la cola más rápido?
    .reveal = Los peces reales nadan más rápido cuanto más rápido baten la cola, casi en línea recta dentro de su rango de crucero, y cada coletazo los lleva unos 0,6 a 0,7 largos del cuerpo (Bainbridge 1958; las revisiones de Webb); el ritmo de la cola no puede subir sin límite porque los músculos solo se contraen hasta cierta rapidez. El pez de Tu y Terzopoulos nada de la misma manera, con sus resortes y una fuerza del agua sencilla. El nuestro: la velocidad crece casi en línea recta hasta 3 coletazos por segundo, y cada coletazo gana solo unos 0,25 largos del cuerpo (nuestra agua no tiene masa añadida y la aleta caudal es pequeña); por encima de 3 coletazos por segundo cada coletazo de más gana menos, y a 5 el pez nada más despacio que a 4: la cola pasiva ya no puede seguir el ritmo, un límite de nuestro modelo de resortes, no el límite muscular de los peces reales.
    .reference = Bainbridge 1958, J. Exp. Biol. 35:109; Webb 1975, Hydrodynamics and energetics of fish propulsion; Tu y Terzopoulos 1994 §3; Shoal: docs/fish-body.md

## Aprender a nadar

inv-learning = Aprender a nadar
    .teaser = Un pez practica a nadar. ¿El que practicó más tiempo nada más lejos?
    .intro = Un tiburón que no sabe nadar prueba movimientos musculares al azar y se queda con los que lo llevan más lejos (recocido simulado). Se guardan copias tras 90, 1440, 2790, 4140, 5490 y 6840 intentos; luego las seis compiten en una carrera.
    .question = ¿La copia que practicó más (6840 intentos) nadará más lejos?
    .choice-clearly = Sí, claramente más lejos
    .choice-just = Sí, pero por muy poco
    .choice-no = No, practicar deja de ayudar
    .run-hint = El tiburón practica el primer ejercicio (nadar lo más lejos que pueda) un poco en cada fotograma: la gráfica bajo el tanque muestra qué tan bien nada. Luego las seis copias compiten en una carrera.
    .prompt-1 = ¿Qué copias ganaron más con su práctica extra?
    .prompt-2 = ¿Por qué los últimos miles de intentos podrían ayudar tan poco?
    .reveal = El tiburón de Tu y Terzopoulos entrenado durante 6840 pasos «gana la carrera con claridad». El nuestro aprende rápido al principio (la copia de 90 intentos apenas se mueve; la de 1440 ya está cerca) y luego casi no mejora: el recocido casi ha convergido a los 4140 intentos, así que las últimas copias llegan a menos de un 1 % unas de otras, y la que más entrenó no siempre gana. Las curvas de aprendizaje de las personas y los animales tienen la misma forma: grandes avances al principio y pequeños al final (la «ley potencial de la práctica», Newell y Rosenbloom 1981).
    .reference = Tu y Terzopoulos 1994 §4 y fig. 7; Newell y Rosenbloom 1981; Shoal: docs/learning.md

## Los resultados de las ejecuciones (src/investigation/measure.rs, outcome.rs).

inv-verdict-agrees = Predijiste «{ $prediction }». { $numbers } La medición coincide con tu predicción.
inv-verdict-instead = Predijiste «{ $prediction }». { $numbers } La medición apunta más bien a «{ $supported }».
inv-curve-verdict-closest = Tu dibujo, «{ $sketch }», es la forma más cercana a la curva medida (en promedio a { $percent } % de la altura de la gráfica).
inv-curve-verdict-other = Tu dibujo, «{ $sketch }», queda en promedio a { $percent } % de la altura de la gráfica de la curva medida; la forma más cercana es «{ $closest }» ({ $closest_percent } %).
inv-csv-curve-low = curva x={ $x } 95% inferior
inv-csv-curve-high = curva x={ $x } 95% superior
inv-loners = solitarios (tanque Individual)
inv-school = cardumen (tanque Grupo)
inv-catches-summary = En { $secs } segundos simulados el tiburón atrapó { $loners ->
        [one] { $loners } pez solitario
       *[other] { $loners } peces solitarios
    } y { $school ->
        [one] { $school } pez
       *[other] { $school } peces
    } del cardumen.
inv-row-caught-loners = peces atrapados, solitarios (tanque Individual)
inv-row-caught-school = peces atrapados, cardumen (tanque Grupo)
inv-unit-fish = peces
inv-unit-fish-caught = peces atrapados
inv-fish-heeded = pez { $fish } (atendió a { $count })
inv-alignment-summary = Inspeccionaste { $fish }: cada uno reaccionó solo a los pocos vecinos que veía. Polarización con la alineación encendida (peso { $weight }): { $on }; apagada: { $off } (medias durante { $secs } s).
inv-row-alignment-on = polarización, alineación encendida ({ $weight })
inv-row-alignment-off = polarización, alineación apagada (0)
inv-row-heeded = vecinos a los que atendió el pez { $fish }
inv-unit-polarization = polarización (0-1)
inv-what-polarization = la polarización
inv-what-speed = la velocidad
inv-curve-point = { $value } en { $x }
inv-curve-summary = Se midió { $what }: { $first } ({ $x_label }), { $last } al final, máximo { $peak }.
inv-curve-none = No se midió ningún punto de { $what }.
inv-row-curve = { $y_label } con { $x_label } { $x }
inv-race-summary = Tras { $secs } s la copia que practicó { $tries } intentos nadó { $last } m; la mejor de las demás, { $best } m ({ $margin } %). La copia con { $first_tries } intentos nadó { $first } m.
inv-row-distance = distancia tras { $tries } intentos
inv-unit-metres-swum = metros nadados
inv-status-catches = { $t } de { $secs } segundos simulados
inv-status-sweep = ejecución { $run } de { $runs } del experimento
inv-status-tail-beat = nadando a { $hz } coletazos por segundo ({ $k } de { $total })
inv-status-open-learning = abre el laboratorio de aprendizaje
inv-status-race = la carrera: { $t } de { $secs } s
inv-status-practising = practicando el primer ejercicio: { $tries } de { $total } intentos
inv-status-alignment = alineación encendida { $on }/{ $secs } s, apagada { $off }/{ $secs } s
inv-experiment-refused = el experimento de la investigación: { $error }

## Pasos rechazados (src/investigation/mod.rs) y enlaces (link.rs).

inv-error-no-prediction = primero confirma una predicción: la ejecución empieza solo después de que hayas predicho
inv-error-locked = la predicción está bloqueada: se confirmó antes de la ejecución
inv-error-no-such-answer = la respuesta { $choice } no existe: hay { $count ->
        [one] { $count } respuesta
       *[other] { $count } respuestas
    }
inv-error-wrong-step = ahora no: este es el paso de { $step }
inv-error-no-result = la ejecución aún no ha terminado
inv-step-name-intro = introducción
inv-step-name-predict = predicción
inv-step-name-run = ejecución
inv-step-name-explain = explicación
inv-step-name-reveal = descubrimiento
inv-error-no-investigation = no hay ninguna investigación abierta
inv-link-unknown = no existe la investigación '{ $id }'; las investigaciones son: { $known }
inv-link-not-an-id = investigation: se esperaba un id como "why-school" (o null para cerrarla), pero llegó { $got }

## La ventana (src/ui/investigation_panel.rs).

inv-button = Investigaciones: predice, ejecuta, explica
    .help = Lecciones guiadas: predice lo que pasará, ejecútalo, explica lo que viste y descubre lo que encontraron los científicos
inv-window-title = Investigación: { $title }
inv-list-title = Investigaciones
inv-list-intro = Predice, ejecuta, explica. Cada una ocupa una parte de una clase; después el tanque sigue siendo tuyo para explorar.
inv-continue = Continuar: { $title } »
    .help = Volver a la investigación que estabas haciendo
inv-minutes = unos { $minutes } minutos
inv-record = Descargar mi registro
    .help = Una página web con tus predicciones, los números medidos, las gráficas y tus explicaciones, para tu maestro; se abre sin Shoal
inv-record-csv = Números (CSV)
    .help = Los números medidos de tus ejecuciones, para una hoja de cálculo
inv-record-next = ábrelo en cualquier navegador web
inv-record-csv-next = ábrelo con una hoja de cálculo
inv-next-predict = Siguiente: predice »
inv-commit = Confirmar mi predicción (se bloquea)
    .help = Una vez confirmada, tu predicción queda bloqueada: no puede cambiar
    .disabled = Primero elige una respuesta
inv-run = Ejecutar »
    .help = Empieza la ejecución: la medición comienza ahora
    .disabled = Primero confirma una predicción
inv-your-prediction = Tu predicción (bloqueada): { $prediction }
inv-next-explain = Siguiente: explica »
inv-question-of = Pregunta { $number } de { $count }
inv-answer-hint = Tu respuesta (va en tu registro)
inv-to-reveal = ¿Qué descubrieron los científicos? »
inv-next-question = Siguiente pregunta »
inv-found = Lo que descubrieron los científicos
inv-your-run = Tu ejecución: { $summary }
inv-sandbox = Ahora el tanque es tuyo: todos los controles funcionan. Cambia algo y observa qué pasa.
inv-others = Otras investigaciones
inv-step-look = 1 Observa
inv-step-predict = 2 Predice
inv-step-run = 3 Ejecuta
inv-step-explain = 4 Explica
inv-step-found = 5 Hallazgos
inv-alignment-off = Apagar alineación
    .help = Pone el impulso de alineación en 0: los peces dejan de copiar a sus vecinos
inv-alignment-on = Encender alineación
    .help = Devuelve el impulso de alineación
inv-alignment-so-far = Polarización hasta ahora: alineación encendida { $on }, apagada { $off }. Peces en los que hiciste clic: { $fish }
inv-none-clicked = ninguno todavía (haz clic en un pez del tanque)

## Las gráficas de la ventana (src/ui/investigation_plot.rs).

inv-plot-your-sketch = tu dibujo
inv-plot-tries = intentos de práctica
inv-plot-measured = medido
inv-plot-interval = intervalo del 95 %
inv-plot-your-prediction = tu predicción
inv-plot-simulated-seconds = segundos simulados

## El registro del estudiante (src/investigation/record.rs).

inv-record-title = Mis investigaciones en Shoal
inv-record-intro = Predice, observa, explica: cada predicción se bloqueó antes de que empezara su ejecución. Cada número de abajo lo midió la simulación de Shoal durante la ejecución.
inv-record-none = Todavía no se ha hecho ninguna investigación.
inv-record-my-prediction = Mi predicción
inv-record-locked = { $prediction } (bloqueada antes de la ejecución)
inv-record-no-prediction = Todavía no hay predicción.
inv-record-measured = Lo que se midió
inv-record-not-finished = La ejecución no ha terminado.
inv-record-my-explanations = Mis explicaciones
inv-record-no-answer = (sin respuesta)
inv-record-table-measured = medición
inv-record-table-value = valor
inv-record-table-unit = unidad
inv-record-svg-measured = medido (barras: intervalo del 95 %)
inv-record-svg-prediction = mi predicción (discontinua)
inv-record-svg-seconds = segundos simulados (de 0 a { $secs })
inv-record-csv-title = # Shoal: los números medidos de mis investigaciones (una fila por número)
inv-record-csv-predicted = # { $id }: predicción "{ $prediction }"
inv-record-byline = { $name }, { $date } a las { $time }
inv-record-no-name = Sin nombre
inv-record-seeds = Semilla: { $seeds }.
inv-record-rerun = Abrir esta corrida otra vez en Shoal (mismos ajustes y semilla)
inv-record-csv-run = # { $id }: semilla { $seeds }; para correrla otra vez: { $link }
inv-student-name = Tu nombre, para tu registro:
    .hint = Nombre y apellido
    .help = Va arriba de tu registro y en el nombre del archivo. Solo este navegador lo recuerda; nunca se envía a ningún lado.
