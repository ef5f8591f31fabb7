<?php
// grafika's check of its quizzes in a real Moodle (docs/contributing.md,
// "Testing against a real Moodle"). Not part of Moodle: run it with the
// PHP of a Moodle installed for testing, never on a live site.
//
//   php grade.php --moodle=MOODLE_ROOT --file=quiz.xml [--format=xml|gift]
//       [--lang=en|id] [--behaviour=deferredfeedback|interactive]
//       [--probes=PROBES.json] [--html=DIR]
//
// It creates a course with its default question bank, imports FILE there
// with Moodle's own importer (qformat_xml or qformat_gift, "Get category
// from file" on), and marks every imported question with the question
// engine, as a quiz attempt would (the chosen behaviour, the chosen user
// interface language: Moodle reads a typed number by its language's
// decimal mark and thousands separator). It prints one JSON object per
// line: first the import ({"import": …}), then one per question and probe:
//
//   {"question": NAME, "probe": P, "responses": [...], "state": STATE,
//    "fraction": F, "blanks": [{"fraction": f, "feedback": TEXT,
//    "complete": bool, "error": TEXT}, ...]}
//
// The probes of every question: "right" (each blank's first 100 % answer
// as Moodle shows it, a number with the interface language's decimal
// mark), "right-point" and "right-comma" (the numbers of "right" with a
// decimal point, with a decimal comma), "zero" (0 in every number blank,
// the rest right), "right-B-K" (the K-th further 100 % answer of blank B:
// another spelling of a word) and "wrong-B-K" (the K-th 0 % answer of
// blank B, as Moodle shows it, the rest right). PROBES.json adds its own: {"NAME or *":
// [{"probe": "P", "responses": ["…" or null (the right answer), …]}]}.
// --html writes each question's review page (all feedback shown) after
// the "right" probe to DIR/NNNN.html.

define('CLI_SCRIPT', true);

$opts = getopt('', ['moodle:', 'file:', 'format::', 'lang::', 'behaviour::', 'probes::', 'html::']);
if (empty($opts['moodle']) || empty($opts['file'])) {
    fwrite(STDERR, "usage: php grade.php --moodle=MOODLE_ROOT --file=QUIZ [--format=xml|gift] [--lang=en|id]"
        . " [--behaviour=deferredfeedback|interactive] [--probes=FILE.json] [--html=DIR]\n");
    exit(2);
}
// (Moodle's setup has globals of its own: ours are kept in $run.)
$run = (object) [];
$run->file = realpath($opts['file']);
$run->format = $opts['format'] ?? (str_ends_with($run->file, '.gift') ? 'gift' : 'xml');
$run->lang = $opts['lang'] ?? 'en';
$run->behaviour = $opts['behaviour'] ?? 'deferredfeedback';
$run->probes = isset($opts['probes']) ? json_decode(file_get_contents($opts['probes']), true) : [];
$run->html = isset($opts['html']) ? realpath($opts['html']) : null;

require($opts['moodle'] . '/config.php');
require_once($CFG->libdir . '/questionlib.php');
require_once($CFG->dirroot . '/course/lib.php');
require_once($CFG->dirroot . "/question/format/{$run->format}/format.php");

\core\session\manager::set_user(get_admin());

/** One JSON line. */
function out(array $line): void {
    echo json_encode($line, JSON_UNESCAPED_UNICODE | JSON_UNESCAPED_SLASHES), "\n";
}

// A course of its own, with its default question bank (in Moodle 5 a bank
// is a course activity; a new course has none until one is made).
$course = create_course((object) [
    'fullname' => 'grafika ' . basename($run->file),
    'shortname' => 'grafika-' . uniqid(),
    'category' => $DB->get_field_select('course_categories', 'MIN(id)', '1 = 1'),
]);
$bank = \core_question\local\bank\question_bank_helper::get_default_open_instance_system_type($course, true);
$context = context_module::instance($bank->id);
$top = question_get_default_category($context->id, true);

// Import as the bank's Import page does.
$class = "qformat_{$run->format}";
$qformat = new $class();
$qformat->setCategory($top);
$qformat->setContexts([$context]);
$qformat->setCourse($course);
$qformat->setFilename($run->file);
$qformat->setRealfilename(basename($run->file));
$qformat->setMatchgrades('error');
$qformat->setCatfromfile(true);
$qformat->setContextfromfile(false);
$qformat->setStoponerror(true);
ob_start();
$ok = $qformat->importpreprocess() && $qformat->importprocess() && $qformat->importpostprocess();
$log = trim(html_to_text(ob_get_clean(), 0, false));
out(['import' => ['ok' => (bool) $ok, 'questions' => count($qformat->questionids),
    'bytes' => filesize($run->file), 'log' => $ok ? '' : $log]]);
if (!$ok) {
    exit(1);
}

/** The blanks of a question: Cloze subquestions, or the question itself. */
function blanks(question_definition $q): array {
    return $q instanceof qtype_multianswer_question ? $q->subquestions : [1 => $q];
}

/** The response variable of blank $i. */
function field(question_definition $q, int $i): string {
    return $q instanceof qtype_multianswer_question ? "sub{$i}_answer" : 'answer';
}

/** Each blank's answers in order, as [text, fraction]. */
function answers(question_definition $blank): array {
    $list = [];
    foreach ($blank->answers as $a) {
        $list[] = [$a->answer, (float) $a->fraction];
    }
    return $list;
}

/** A blank's answer as Moodle shows it: a number with the interface's mark. */
function shown(question_definition $blank, string $answer): string {
    return $blank instanceof qtype_numerical_question ? str_replace('.', $blank->ap->get_point(), $answer) : $answer;
}

/** The probes of a question (see the top of the file). */
function probes_of(question_definition $q, array $extra): array {
    $right = [];
    $point = [];
    $numeric = [];
    foreach (blanks($q) as $i => $b) {
        $first = array_values(array_filter(answers($b), fn($a) => $a[1] >= 1.0))[0][0] ?? '';
        $point[$i] = $first;
        $right[$i] = shown($b, $first);
        $numeric[$i] = $b instanceof qtype_numerical_question;
    }
    $list = ['right' => $right];
    $list['right-point'] = $point;
    $list['right-comma'] = array_map(fn($r, $n) => $n ? str_replace('.', ',', $r) : $r, $point, $numeric);
    $list['right-comma'] = array_combine(array_keys($point), $list['right-comma']);
    $zero = $right;
    foreach ($numeric as $i => $n) {
        if ($n) {
            $zero[$i] = '0';
        }
    }
    $list['zero'] = $zero;
    foreach (blanks($q) as $i => $b) {
        [$k, $n] = [0, 0];
        foreach (answers($b) as [$text, $fraction]) {
            if ($fraction == 0.0) {
                $k++;
                $list["wrong-$i-$k"] = array_replace($right, [$i => shown($b, $text)]);
            } else if ($fraction >= 1.0 && $text !== $point[$i]) {
                $n++;
                $list["right-$i-$n"] = array_replace($right, [$i => shown($b, $text)]);
            }
        }
    }
    foreach (array_merge($extra['*'] ?? [], $extra[$q->name] ?? []) as $p) {
        $r = $right;
        foreach (array_values($p['responses']) as $k => $v) {
            $i = array_keys($right)[$k] ?? null;
            if ($i !== null && $v !== null) {
                $r[$i] = $v;
            }
        }
        $list[$p['probe']] = $r;
    }
    return $list;
}

/** Marks one probe in a fresh attempt; returns its line. */
function mark(question_definition $q, string $probe, array $responses, string $behaviour,
        context $context, ?string $htmlfile): array {
    $quba = question_engine::make_questions_usage_by_activity('core_question_preview', $context);
    $quba->set_preferred_behaviour($behaviour);
    $slot = $quba->add_question(question_bank::load_question($q->id), 1);
    $quba->start_all_questions();
    $def = $quba->get_question($slot);
    $data = [];
    foreach ($responses as $i => $r) {
        $data[field($def, $i)] = $r;
    }
    if ($behaviour === 'interactive') {
        $data['-submit'] = 1; // the Check button
    }
    $quba->process_action($slot, $data);
    $checked = (string) $quba->get_question_state($slot);
    $quba->finish_all_questions();
    $blanks = [];
    foreach (blanks($def) as $i => $b) {
        $resp = ['answer' => $responses[$i]];
        [$fraction] = $b->grade_response($resp);
        $feedback = '';
        if ($b instanceof qtype_numerical_question) {
            [$value, , $multiplier] = $b->ap->apply_units($responses[$i]);
            $answer = $b->get_matching_answer($value, $multiplier);
            $feedback = $answer ? html_to_text($answer->feedback, 0, false) : '';
        } else if (method_exists($b, 'get_matching_answer')) {
            $answer = $b->get_matching_answer($resp);
            $feedback = $answer ? html_to_text($answer->feedback, 0, false) : '';
        }
        $blanks[] = ['response' => $responses[$i], 'fraction' => $fraction, 'feedback' => trim($feedback),
            'complete' => $b->is_complete_response($resp), 'error' => $b->get_validation_error($resp)];
    }
    if ($htmlfile !== null) {
        $options = new question_display_options();
        $options->feedback = $options->generalfeedback = $options->rightanswer = question_display_options::VISIBLE;
        $options->marks = question_display_options::MARK_AND_MAX;
        file_put_contents($htmlfile, $quba->render_question($slot, $options));
    }
    return ['question' => $q->name, 'probe' => $probe, 'behaviour' => $behaviour,
        'checked' => $checked, 'state' => (string) $quba->get_question_state($slot),
        'fraction' => $quba->get_question_fraction($slot), 'blanks' => $blanks];
}

global $PAGE;
$PAGE->set_context($context);
$PAGE->set_url('/');
// The student's interface language (set after the course is made, which
// sets the page's language): its decimal mark and thousands separator are
// how a typed number is read.
get_string_manager()->reset_caches();
if ($run->lang !== 'en' && !get_string_manager()->translation_exists($run->lang, false)) {
    fwrite(STDERR, "no language pack '{$run->lang}' in this Moodle\n");
    exit(2);
}
force_current_language($run->lang);
foreach ($qformat->questionids as $n => $id) {
    $q = question_bank::load_question($id);
    foreach (probes_of($q, $run->probes) as $probe => $responses) {
        $html = ($run->html !== null && $probe === 'right') ? sprintf('%s/%04d.html', $run->html, $n + 1) : null;
        out(mark($q, $probe, $responses, $run->behaviour, $context, $html));
    }
}
