# El estudio del maestro: su ventana, los botones O / B / ?, el enlace para
# los estudiantes, la tarjeta de la pregunta, lo que un estudiante ve de una
# regla y los errores de las reglas.

studio-button = Estudio del maestro
    .help = Oculta, bloquea o convierte en misterio cualquier control, escribe tu propia pregunta y comparte el resultado con tu clase como enlace y código QR
studio-mystery-value = ? (valor misterioso)
    .help = Tu maestro ocultó este número. Observa lo que hacen los peces y descubre cuál debe ser.
studio-locked = Bloqueado por tu maestro para esta lección
studio-toggle-hide = O
    .help = Ocultar: los estudiantes no ven este control
studio-toggle-lock = B
    .help = Bloquear: los estudiantes lo ven en gris y no pueden cambiarlo
studio-toggle-mystery = ?
    .help = Misterio: los estudiantes ven los peces pero no este número (también queda bloqueado)
studio-toggle-hide-name = Ocultar { $key }
studio-toggle-lock-name = Bloquear { $key }
studio-toggle-mystery-name = Convertir { $key } en un misterio
studio-toggle-help = { $help } ({ $key })
studio-teacher-asks = Tu maestro pregunta
studio-share = Compartir con la clase
    .help = Un enlace y un código QR que abren este ajuste en la vista del estudiante
studio-share-intro = Proyecta este código QR o envía el enlace: abre Shoal tal como está ahora, en la vista del estudiante (con tus reglas en vigor y tu pregunta a la vista).
studio-copy-link = Copiar enlace
    .help = Pone el enlace de los estudiantes en el portapapeles
studio-link-copied = Enlace de los estudiantes copiado. Abre la vista del estudiante: tus reglas en vigor y tu pregunta a la vista.
studio-open-student-view = Abrir la vista del estudiante en una pestaña nueva
    .help = Revisa lo que verán tus estudiantes
studio-intro = Junto a cada control del panel lateral: O lo oculta a tus estudiantes, B lo bloquea (lo ven en gris), ? convierte su valor en un misterio (ven los peces, no el número, y deben descubrirlo; también queda bloqueado).
studio-intro-note = La página de los estudiantes empieza con los ajustes que tienes ahora: elige primero la escena, los controles deslizantes y la semilla.
studio-question = Tu pregunta para la clase
studio-question-hint = p. ej., ¿Qué tanto copian estos peces a sus vecinos?
studio-rules = Reglas
studio-no-rules = Ninguna todavía: todos los controles están libres.
studio-rule = { $key }: { $what }
studio-rule-hidden = oculto
studio-rule-locked = bloqueado
studio-rule-mystery = misterio
studio-remove = Quitar

# Por qué se rechaza un estudio (en un enlace o en shoal.set).
studio-error-student-view = esta es la vista del estudiante del enlace de un maestro: aquí no se puede cambiar su estudio (abre Shoal sin el enlace para editarlo)
studio-error-kept = { $how ->
    [mystery] es un valor misterioso
    [hidden] está oculto
   *[locked] está bloqueado
} por el estudio del maestro: los estudiantes no pueden cambiarlo (cambiarlo lo cambiaría a través de otro control)
studio-error-question-long = la pregunta tiene { $count } caracteres: como máximo { $max }
studio-error-too-many-rules = { $count } reglas: como máximo { $max }
studio-error-not-an-object = se esperaba un objeto como {"{"}"question": "…", "rules": {"{"}"left.alignment": {"{"}"mystery": true{"}"}{"}"}{"}"}, pero llegó { $value }
studio-error-expected-bool = se esperaba true o false, pero llegó { $value }
studio-error-expected-text = se esperaba un texto, pero llegó { $value }
studio-error-rules-not-an-object = se esperaba un objeto de reglas por control, como {"{"}"left.alignment": {"{"}"locked": true{"}"}{"}"}, pero llegó { $value }
studio-error-unknown-field = desconocido: los ajustes del estudio son student_view, question y rules
studio-error-rule-not-an-object = se esperaba una regla como {"{"}"hidden": true{"}"} (o null para quitarla), pero llegó { $value }
studio-error-unknown-flag = marca desconocida '{ $flag }': una regla tiene hidden, locked y mystery
studio-error-flag-not-bool = '{ $flag }' debe ser true o false, pero llegó { $value }
studio-error-no-control = ningún control se llama '{ $key }': las reglas nombran un control por su ajuste, como en settings(), p. ej., left.alignment, speed o physics.current_m_per_s
