# Una clase juntos (issue 37): iniciar una clase y unirse a ella, el panel del
# docente y lo que un estudiante lee sobre su clase.
class-start = Iniciar una clase
    .help = Da a tu clase un código para unirse: ven tu investigación o la configuración del estudio, y tú ves sus predicciones, ejecuciones y respuestas
class-join = Unirse a una clase
    .help = Únete a la clase de tu docente con su código y un apodo
class-start-intro = Elige qué hará la clase. El tanque de cada estudiante usa su propia semilla (la semilla de la clase más su orden de llegada).
class-lesson-studio = La configuración actual del estudio (sus bloqueos y misterios)
class-start-go = Iniciar la clase
class-starting = Iniciando…
class-start-failed = No se pudo iniciar la clase: { $reason }
class-join-intro = Escribe el código que muestra tu docente y un apodo. Usa un nombre de pila o uno inventado: es lo único sobre ti que guarda el servidor de la clase.
class-code = Código de la clase
class-nickname = Apodo
    .help = Como máximo 24 caracteres
class-join-go = Unirse
class-bad-code = Un código de clase tiene 6 letras y cifras, tal como lo muestra tu docente.
class-bad-nickname = Escribe un apodo de 1 a 24 caracteres.
class-dashboard = Panel de la clase
class-code-to-join = Código de la clase (o escanea el código QR):
class-copy-teacher-link = Copiar mi enlace de docente
    .help = El enlace secreto que abre este panel en otro ordenador. No lo muestres a los estudiantes.
class-teacher-link-copied = Enlace de docente copiado. Guárdalo en secreto: quien lo tenga ve toda la clase.
class-waiting-for-view = Esperando al servidor de la clase…
class-pacing = Ritmo
class-hold-at = Detener la clase en
class-no-hold = sin detener
class-release = Liberar el paso siguiente
    .help = Deja que la clase avance un paso más
class-pause-all = Pausar todos los tanques
    .help = Se detiene el tanque de cada estudiante: «mirad aquí»
class-reveal = Revelar las predicciones
    .help = Los estudiantes ven cuántos eligieron cada respuesta (nunca quién)
class-send-setting = Enviar mi ajuste a todos
    .help = El tanque de cada estudiante toma los ajustes de tu tanque (su semilla se mantiene; los bloqueos del estudio se respetan)
class-setting-too-large = Este ajuste es demasiado grande para enviarlo.
class-roster = Estudiantes: { $count }
class-step-counts = Observar { $look } · Predecir { $predict } · Ejecutar { $run } · Explicar { $explain }
class-col-student = Estudiante
class-col-step = Paso
class-col-prediction = Predicción
class-col-runs = Ejecuciones
class-student-n = Estudiante { $n }
class-predictions = Predicciones
class-predictions-hidden = Ocultas a los estudiantes hasta que las reveles.
class-predictions-revealed = Los estudiantes ven estos recuentos.
class-predictions-none = Aún no hay predicciones.
class-pooled = El resultado conjunto (cada ejecución, con su propia semilla)
class-pooled-none = Aún no hay ejecuciones.
class-pooled-line = Media { $mean } (intervalo del 95 % de { $low } a { $high }), n = { $n } { $n ->
        [one] ejecución
       *[other] ejecuciones
    } de { $students } { $students ->
        [one] estudiante
       *[other] estudiantes
    }
class-pooled-line-one = Media { $mean }, n = { $n } { $n ->
        [one] ejecución
       *[other] ejecuciones
    } de { $students } { $students ->
        [one] estudiante
       *[other] estudiantes
    } (un intervalo necesita dos ejecuciones)
class-answers = Respuestas de explicación
class-answers-none = Aún no hay respuestas.
class-anonymise = Anonimizar
    .help = Mostrar «Estudiante 1, 2, …» en lugar de los apodos (para el proyector); la descarga conserva los apodos
class-download = Descargar los datos de la clase
    .help = El CSV de la clase: la semilla, la predicción y los valores medidos de cada estudiante
class-download-failed = No se pudieron descargar los datos de la clase: { $reason }
class-delete = Borrar la clase
    .help = Borra ahora del servidor la clase y todo lo que contiene
class-delete-confirm = ¿Borrar del servidor esta clase y todo el trabajo de sus estudiantes? No se puede deshacer.
class-delete-yes = Borrarla
class-delete-no = Conservarla
class-delete-failed = No se pudo borrar la clase: { $reason }
class-deleted = La clase se borró del servidor.
class-leave = Salir de la clase
    .help = Olvidar esta clase en este navegador (la clase sigue en el servidor)
class-step-look = observar
class-step-predict = predecir
class-step-run = ejecutar
class-step-explain = explicar
class-connected = conectado
class-connecting = conectando…
class-reconnecting = reconectando en { $secs } s
class-link-ended = sin conexión
class-status = Clase { $code }: { $link }
class-status-waiting = Clase { $code }: { $link }, { $count } { $count ->
        [one] mensaje
       *[other] mensajes
    } en espera
class-you-are = Eres { $nickname } (estudiante { $order }, semilla { $seed })
class-held = Tu docente ha detenido la clase en «{ $step }»: espera antes de seguir.
class-paused-notice = Mirad aquí: vuestro docente ha pausado todos los tanques.
class-revealed = Las predicciones de la clase:
class-refused = El servidor de la clase rechazó tu { $kind }: { $reason }
class-ended = No se puede llegar a la clase: { $reason }
class-unknown-lesson = Esta versión de Shoal no puede abrir la lección de la clase ({ $lesson }).
