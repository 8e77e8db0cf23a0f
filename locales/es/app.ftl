# Las palabras propias de la app: la ventana Teclado y lo que dicen las teclas
# (src/app/keys.rs), avisos y vistas (src/app/mod.rs, views.rs, facade.rs).

keys-title = Teclado
keys-play = Espacio o P
    .does = Reanudar o pausar (Espacio pulsa un botón si hay uno con el foco)
keys-step = S
    .does = Avanzar un paso
keys-reset = R
    .does = Reiniciar la simulación
keys-scenes = 1 a 5
    .does = Acuario, Laboratorio de cardumen, Peces físicos, Arrecife, Laboratorio de aprendizaje
keys-speed = { $slower } y { $faster }
    .does = Más lento y más rápido (la mitad y el doble de velocidad)
keys-arrows = Flechas
    .does = Girar la cámara alrededor del tanque (cuando ningún control tiene el foco)
keys-zoom = + y −
    .does = Acercar y alejar la cámara
keys-view = V
    .does = Devolver la cámara a su lugar
keys-next = N y B
    .does = Seleccionar el pez siguiente o el anterior, y oír lo que hace
keys-follow = F
    .does = La cámara sigue al pez seleccionado, o deja de seguirlo (Peces físicos, Arrecife)
keys-describe = D
    .does = Describir el tanque: lo que hacen los peces y lo que muestran las gráficas
keys-tab = Tab y Mayús+Tab
    .does = Moverte entre los controles; Enter o Espacio pulsa uno
keys-help = ?
    .does = Mostrar u ocultar esta lista
keys-screen-reader = Con un lector de pantalla, cada control está en la página; el tanque se describe en una región en vivo, y D lo lee todo.
keys-close = Cerrar
keys-cannot-pick = En { $scene } no puedes elegir un pez.
keys-following = La cámara sigue al pez seleccionado.
keys-select-first = Primero selecciona un pez (N o B); luego F lo sigue.
keys-not-following = La cámara ya no sigue al pez.
keys-cannot-follow = En { $scene } la cámara no sigue a ningún pez.
keys-left-tank = Tanque izquierdo
keys-right-tank = Tanque derecho

app-no-gpu = Shoal necesita un renderizador con GPU (WebGPU o WebGL2), y no se pudo iniciar ninguno.
app-bench-title = Prueba de rendimiento
app-bench-done = Listo. Cifras para esta computadora y este navegador:
app-bench-measuring = Midiendo… (alrededor de un minuto)
app-bench-scene = escena
app-bench-fish = peces
app-bench-steps = pasos/s
app-bench-fish-steps = pasos de pez/s
app-bench-frame = cuadro ms
app-bench-cpu = CPU ms
app-bench-annealing = Laboratorio de aprendizaje: { $rate } evaluaciones de recocido simulado/s
app-bench-experiment = Experimento { $name }: { $rate } simulaciones/s ({ $runs } simulaciones de { $steps } pasos, un hilo)
app-status = Estado
app-controls = Controles
    .help = Muestra el panel de controles
app-reset-view = Vista inicial (V)
    .help = Devuelve la cámara a lo que muestra esta escena
notice-link-copied = Enlace copiado. Pégalo en un mensaje o en una página web: abre Shoal exactamente con estos ajustes.
notice-csv-next = ábrelo con una hoja de cálculo
notice-ok = Aceptar
    .help = Oculta este mensaje
notice-experiment-link-copied = Enlace copiado: abre Shoal en este experimento y lo vuelve a correr, con los mismos números.
notice-investigation-link-error = Este enlace no pudo abrir su investigación: { $error }. Se abrió el resto del enlace.
notice-experiment-link-error = Este enlace no pudo abrir su experimento: { $error }. Se abrió el resto del enlace.
notice-experiment-reopened = Este enlace volvió a abrir el experimento «{ $name }»: sus simulaciones empiezan ahora, las mismas y con los mismos números que cuando se hizo el enlace.

# Se perdió el dispositivo gráfico (la computadora se suspendió o cambió de
# pantalla) y Shoal volvió a dibujar con uno nuevo.
app-gpu-recovered = Los gráficos se perdieron por un momento (la computadora se suspendió o cambió de pantalla). Shoal volvió a dibujar el tanque; los peces, el reloj y tus ajustes siguieron igual.
app-gpu-lost-title = Shoal perdió sus gráficos y no pudo recuperarlos
app-gpu-lost-why = La computadora se suspendió, cambió de pantalla o reinició sus gráficos. Si vuelves a cargar la página, Shoal empieza de nuevo con los mismos ajustes (están en la dirección de la página).
