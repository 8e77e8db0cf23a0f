# El laboratorio de bancos de peces y el acuario: el panel de los boids (src/ui/boids_panel.rs).

boids-tool-look = Mirar
    .help = Arrastra para girar el tanque; usa la rueda para acercar.
boids-tool-add-rock = Poner roca
    .help = Haz clic en la arena para poner una roca ahí.
boids-tool-move-rock = Mover roca
    .help = Arrastra una roca o un pilar a otro lugar.
boids-tool-remove = Quitar
    .help = Haz clic en una roca, un pilar o una repisa para quitarlo.
boids-compare = Comparar dos tanques
    .help = Muestra dos tanques uno al lado del otro, con los mismos peces en el mismo punto de partida. Dales impulsos distintos y mira qué tan diferente se comportan.
boids-show-vision = Mostrar visión
    .help = Dibuja lo que ve cada pez: su campo de visión y líneas hacia los vecinos en los que se fija
boids-edit = Editar:
    .help = Elige qué tanque cambian los controles de abajo
boids-rocks = Rocas
    .help = Cambia las rocas del tanque con el ratón
boids-rock-tools = herramientas de rocas
boids-restore-rocks = Volver a las rocas de la semilla
    .help = Deshace todos los cambios de rocas en este tanque
boids-preset-mystery = ? (misterio)
boids-rock-add-middle = Poner una roca en el centro
    .help = Sin ratón: una roca nueva sobre la arena, en el centro del tanque
boids-rock-no-room = No hay lugar libre para otra roca.
boids-no-rocks = No hay rocas en este tanque.
boids-rock-previous = Roca anterior
boids-rock-next = Roca siguiente
boids-rock-where = Roca { $number } de { $count }: a { $left } m de la izquierda, a { $front } m del frente
boids-rock-left = Izquierda
    .name = Mover la roca a la izquierda
boids-rock-right = Derecha
    .name = Mover la roca a la derecha
boids-rock-back = Atrás
    .name = Mover la roca hacia atrás
boids-rock-front = Adelante
    .name = Mover la roca hacia adelante
boids-rock-move-help = Mueve esta roca { $step } m
boids-rock-remove-this = Quitar esta roca
boids-rock-cannot-go = Esa roca no puede ir ahí: { $reason }
boids-tank-left = Tanque izquierdo
boids-tank-right = Tanque derecho
boids-tank-top = Tanque de arriba
boids-tank-bottom = Tanque de abajo

# Las gráficas de las medidas bajo el tanque (src/ui/metrics_panel.rs).

metrics-polarization = Polarización
    .help = Cuánto nadan todos los peces en la misma dirección: la longitud del promedio de sus rumbos. Alta (cerca de 1): todos apuntan hacia el mismo lado, como soldados en un desfile. Baja (cerca de 0): apuntan cada uno para un lado, o dan vueltas en círculo (entonces el remolino es alto).
metrics-milling = Remolino
    .help = Cuánto giran los cardúmenes alrededor de su propio centro, como un remolino. Alto (cerca de 1): un anillo de peces que da vueltas alrededor de un hueco en el medio. Bajo (cerca de 0): cardúmenes que nadan en línea recta, o peces solitarios. Solo cuenta un grupo de al menos 5 peces que se mantienen a menos de 1,5 largos de cuerpo entre sí, y solo la parte de su giro que va más allá de lo que darían rumbos al azar; por eso los peces solitarios dispersos marcan 0.
metrics-nearest = Vecino más cercano (largos de cuerpo)
    .short = Vecino más cercano
    .help = Qué tan lejos está, en promedio, cada pez de su vecino más cercano, medido en largos de pez. Bajo (cerca de 1): los peces nadan juntos, porque un cardumen se mantiene a un largo de cuerpo, más o menos. Alto (2 o más): los peces están repartidos por todo el tanque.
metrics-groups = Grupos
    .help = Cuántos grupos separados hay: los peces a menos de dos largos de cuerpo van juntos, así que un pez solitario es un grupo de uno. 1: todos los peces están en un solo cardumen. Alto (decenas): los peces nadan solos o en grupitos.
metrics-speed = Rapidez media (m/s)
    .short = Rapidez media
    .help = Qué tan rápido nadan los peces en promedio, en metros por segundo. Alta: los peces van de un lado a otro a toda prisa; baja: pasean despacio (un cardumen apretado suele nadar más lento que los peces solitarios, porque cada pez frena para mantener su lugar).
metrics-line-solid = continua
metrics-line-dashed = discontinua
metrics-line-dotted = punteada
metrics-tank-line = { $label } (línea { $line })
metrics-urge-contain = contener
metrics-urge-align = alinear
metrics-urge-cohere = juntarse
metrics-urge-separate = separar
metrics-urge-avoid = esquivar
metrics-urges = Impulsos usados (% de los movimientos)
    .short = Impulsos usados
    .help = Qué tan seguido se usó cada impulso en el último segundo: contención, alineación, cohesión, separación, evasión. En el modo Mezcla, todos los impulsos actúan en cada movimiento (100 % cada uno, mezclados según su peso); en los modos de un solo impulso, las proporciones siguen los pesos. Con dos tanques, la barra de arriba de cada par es la del tanque izquierdo (o de arriba) y la de abajo, la de la otra.
metrics-percent = { $value } %

# En qué se fija el pez elegido (src/ui/boids_attention.rs).

boids-urge-containment = Contención
    .help = contención (quedarse dentro del tanque)
boids-urge-alignment = Alineación
    .help = alineación (nadar como los vecinos)
boids-urge-cohesion = Cohesión
    .help = cohesión (ir hacia el centro de los vecinos)
boids-urge-separation = Separación
    .help = separación (guardar espacio)
boids-urge-avoidance = Evasión
    .help = evasión (esquivar los obstáculos)
boids-result-arrow = resultado
boids-rule-none = ninguno
boids-rule-blended = Mezcla: todos los impulsos con peso tiran a la vez, cada uno según la parte de su peso (las flechas suman el resultado).
boids-rule-classic = Clásico: solo actúa el impulso más urgente (su peso × cuánto hace falta ahora). En este paso: { $chosen }.
boids-rule-direct-alternate = Alternancia directa: se tira un dado una vez, y cada impulso cuyo peso le gana actúa con toda su fuerza. En este paso: { $chosen }.
boids-rule-monte-carlo = Monte Carlo: un impulso sale sorteado; los pesos más grandes tienen más boletos. En este paso: { $chosen }.
boids-leader-alone = Ningún pez es el líder: el pez { $fish } no ve a ningún otro pez ahora, así que solo lo guían el tanque, las rocas y su propio deambular.
boids-leader-neighbours = { $count ->
    [one] Ningún pez es el líder: el pez { $fish } solo reacciona al { $count } vecino que ve, y ese vecino, a los suyos. La forma del cardumen sale de todas estas pequeñas reacciones juntas.
   *[other] Ningún pez es el líder: el pez { $fish } solo reacciona a los { $count } vecinos que ve, y cada uno de ellos, a los suyos. La forma del cardumen sale de todas estas pequeñas reacciones juntas.
}
boids-attention-title = En qué se fija el pez { $fish }
boids-attention-title-tank = En qué se fija el pez { $fish } ({ $tank })
boids-let-go = Soltar
    .help = Dejar de mostrar este pez (o haz clic en el agua)
boids-attention-not-yet = Presiona Reanudar o Paso: el pez no ha nadado desde que cambiaron los ajustes, así que todavía no hay nada que mostrar.
boids-attention-key = Flechas desde el pez (con anillo amarillo): cada impulso, más larga cuanto más fuerte; continua si se usó en este paso, discontinua si no; la blanca es el resultado. Anillos blancos: los vecinos en los que se fija.
boids-urge = Impulso
boids-strength = Fuerza
    .help = Qué tan fuerte tira el impulso, según lo pesa el modo de control: la aceleración que pide, en metros por segundo por segundo
boids-used = ¿Se usó?
boids-used-yes = sí
boids-used-always = siempre
boids-mystery = ?
    .help = Un valor misterioso: tu maestro lo escondió
boids-wander = Deambular
    .help = Su propio vagar: actúa además de cualquier modo de control
boids-fleeing = Huyendo de un tiburón
    .help = Vio un tiburón (o sintió la ola que empuja, o vio huir a un vecino) y nada lejos de él, además de cualquier modo de control. Mientras huye, su peso de cohesión cuenta el doble y su peso de separación la mitad: un cardumen asustado se aprieta.
boids-fear-weights = Mientras huye, el susto cambia dos de sus pesos: cohesión { $cohesion } (×{ $cohesion_factor }) y separación { $separation } (×{ $separation_factor }), así que un cardumen asustado se aprieta.
boids-fear-weights-hidden = Mientras huye, el susto cambia dos de sus pesos: cohesión ×{ $cohesion_factor } y separación ×{ $separation_factor }, así que un cardumen asustado se aprieta.
boids-result = Resultado
    .help = La dirección que recibió el pez en este paso (flecha blanca)
boids-speed-after = Rapidez
    .help = Su rapidez después del paso
boids-heeds-none = No se fija en ningún vecino: no ve a ningún otro pez.
boids-heeds = { $count ->
    [one] Se fija en { $count } vecino (con anillo): el pez { $fish }.
   *[other] Se fija en { $count } vecinos (con anillo): los peces { $fish }.
}
boids-far-school = También ve un grupo de peces lejano y se siente un poco atraído hacia él.
boids-leader = ¿Hay un líder?

# Los controles y gráficas de los peces físicos (src/ui/physics_panel.rs).

physics-title = Peces físicos
physics-behaviour = Los peces…
    .block = cómo nadan
physics-show-body = Mostrar masas y resortes
    .help = Dibuja el esqueleto de cada pez: los puntos blancos son las 23 masas y las líneas, los resortes. Los 12 músculos brillan en rojo cuando tiran y en azul pálido cuando descansan
physics-show-forces = Mostrar fuerzas
    .help = Amarillo: el agua que empuja el cuerpo (el empuje sobre la cola que se agita impulsa al pez hacia adelante). Verde: a dónde quiere ir el pez. Blanco: a dónde va. Azul: la corriente
physics-selected-fish = Pez elegido
    .help = Haz clic en un pez del tanque para elegirlo: así podrás guiarlo a mano, seguirlo con la cámara y ver sus músculos.
physics-selected-a-fish = Elegido: pez { $index }
physics-selected-a-shark = Elegido: tiburón { $index }
physics-deselect = Soltar
    .help = Deja de seguir a este pez
physics-follow = La cámara lo sigue
    .help = Mantiene a este pez en el centro de la vista mientras nada
physics-hand = Guiarlo a mano
    .help = Tú das las órdenes: qué tan rápido bate la cola y cuándo gira. Los demás peces se siguen guiando solos
physics-turn-left = Girar a la izquierda
physics-turn-right = Girar a la derecha
physics-turn-help = Contrae rápido los músculos de un lado y luego los suelta despacio: el pez se dobla y da la vuelta
physics-side-left = izquierda
physics-side-right = derecha
physics-plots-hint = Haz clic en un pez para ver trabajar sus doce músculos y qué tan rápido nada.
physics-muscles-front = Músculos delanteros (girar)
physics-muscles-middle = Músculos del medio (girar y nadar)
physics-muscles-tail = Músculos de la cola (nadar)
physics-muscles = Músculos
    .help = Qué tan fuerte tira cada músculo de esta parte, de 0 (en reposo) a 1 (contraído del todo), en los últimos segundos. Líneas bermellón continuas: el lado izquierdo del pez; líneas azules discontinuas: su lado derecho (dos músculos cada uno; el de arriba, más grueso que el de abajo). Izquierda y derecha se turnan: ese es el coletazo. Ondas altas: el pez mueve la cola con fuerza para nadar rápido; líneas planas cerca de 0: se desliza; un lado alto un momento mientras el otro descansa: gira.
physics-muscle-top = { $side } arriba
physics-muscle-bottom = { $side } abajo
physics-speed = Rapidez (m/s)
    .help = Qué tan rápido se mueve el centro del pez, en metros por segundo. Alta: nada con fuerza, moviendo la cola; baja o cerca de 0: se desliza o se queda quieto. Es normal que suba y baje un poco con cada coletazo.
physics-speed-line = rapidez

# Los paneles bajo el tanque (src/ui/bottom_panel.rs).

metrics-bottom-panel =
    .name = Gráficas y lecturas

# La línea de estado bajo el tanque (src/ui/status_line.rs).

status-fps = { $fps } FPS
    .help = Imágenes dibujadas por segundo
status-steps = { $steps } pasos/s
    .help = Pasos de simulación calculados por cada segundo de tiempo real
status-tank-pixels = , tanque al { $percent } % de los píxeles
status-graphics =
    .help = El sistema gráfico que tu navegador le dio a Shoal: WebGPU es el más nuevo; WebGL2 funciona en todos los demás. «tanque al N % de los píxeles»: los gráficos no dan abasto, así que el tanque se dibuja con menos píxeles para que se mueva con fluidez (Vista › Detalle del tanque)
status-time = t = { $seconds } s
    .help = Tiempo simulado desde el inicio
status-fish-mystery = ? peces
    .help = Tu maestro escondió el número de peces: cuéntalos, o descúbrelo por lo que hacen
status-paused = en pausa
status-slowed = más lento
    .help = Esta computadora no puede seguir la velocidad elegida, así que la simulación va más lenta de lo pedido (no se salta nada: los peces solo se mueven en cámara lenta). Prueba con menos peces o con una velocidad menor.

## Lo que hacen los peces físicos (src/sim/physics/world.rs).
physics-behaviour-school = Cardumen
    .explanation = Los peces se orientan con los impulsos del cardumen y sus músculos los siguen.
physics-behaviour-wander = Deambular
    .explanation = Cada pez explora por su cuenta.
physics-behaviour-drift = A la deriva
    .explanation = Los músculos descansan: los peces se deslizan hasta detenerse y la corriente los lleva.

# Lo que hace cada modo de control, bajo su nombre (ControlMode::explanation).
boids-mode-blended-explanation = Todos los impulsos tiran un poco a la vez, mezclados según su peso.
boids-mode-classic-explanation = En cada momento el pez sigue solo su impulso más urgente.
boids-mode-direct-alternate-explanation = En cada momento cada impulso tira un dado; los impulsos con pesos grandes ganan la tirada más a menudo.
boids-mode-monte-carlo-explanation = En cada momento el pez elige un impulso por lotería; los pesos más grandes tienen más boletos.
