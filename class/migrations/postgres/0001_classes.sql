-- Protocol v1 schema (PostgreSQL). Times are Unix seconds.
CREATE TABLE classes (
    code TEXT PRIMARY KEY,
    teacher_hash TEXT NOT NULL,
    seed BIGINT NOT NULL,
    setup TEXT NOT NULL,
    created_at BIGINT NOT NULL,
    held_step TEXT,
    paused BIGINT NOT NULL DEFAULT 0,
    revealed BIGINT NOT NULL DEFAULT 0,
    anonymise BIGINT NOT NULL DEFAULT 0,
    setting TEXT,
    next_join BIGINT NOT NULL DEFAULT 0
);
CREATE TABLE students (
    id TEXT PRIMARY KEY,
    class_code TEXT NOT NULL REFERENCES classes(code) ON DELETE CASCADE,
    token_hash TEXT NOT NULL UNIQUE,
    nickname TEXT NOT NULL,
    join_order BIGINT NOT NULL,
    step TEXT NOT NULL DEFAULT 'look',
    prediction TEXT,
    answer TEXT,
    UNIQUE (class_code, join_order)
);
CREATE TABLE results (
    student_id TEXT NOT NULL REFERENCES students(id) ON DELETE CASCADE,
    client_id TEXT NOT NULL,
    levels TEXT NOT NULL,
    measure TEXT NOT NULL,
    value DOUBLE PRECISION NOT NULL,
    PRIMARY KEY (student_id, client_id, measure)
);
CREATE TABLE processed (
    class_code TEXT NOT NULL REFERENCES classes(code) ON DELETE CASCADE,
    sender TEXT NOT NULL,
    client_id TEXT NOT NULL,
    reply TEXT NOT NULL,
    PRIMARY KEY (sender, client_id)
);
CREATE INDEX students_class ON students(class_code);
CREATE INDEX classes_created ON classes(created_at);
