# Writes the Gold diagnostics cases: each source comes from an example of the manual's error
# table (2.7.2), wrapped in the few lines that make it a program; the expected errors are
# given by (line, text at which the error points, code) and turned into line:col here.
import os, re
texts = {}
for l in open('/work/main/src/dialects/gold/gold_errors.def'):
    m = re.match(r'GOLD_ERROR\((\d+), \w+, "((?:[^"\\]|\\.)*)"', l)
    if m: texts[int(m.group(1))] = m.group(2).replace('\\"', '"')
cases = {}
def case(name, src, expect):
    cases[name] = (src, expect)

case('01_bad_format_double_colon', '''// Manual 2.7.2, error 1: "for k = 1::10" (double colon between 1 and 10).
function f()
int k
for k = 1::10
end
return
''', [(4, ':10', 1)])
case('01_bad_format_empty_parens', '''// Manual 2.7.2, error 1: "b = a + ( )" (empty expression in parentheses).
function f()
int a, b
b = a + ( )
return
''', [(4, '( )', 1)])
case('01_bad_format_colon_outside_for', '''// Manual 2.7.2, error 1: "k = 1:2:20" (a colon expression used outside a for statement).
function f()
int k
k = 1:2:20
return
''', [(4, ':2', 1)])
case('02_empty_expression', '''// Manual 2.7.2, error 2: "a =" (the right-hand expression is missing).
function f()
int a
a =
return
''', [(4, '=', 2)])
case('03_stack_is_full', '''// Manual 1.9: parentheses nest to 16 levels; the 17th overflows the stack (error 3).
function f()
int a
a = (((((((((((((((((1)))))))))))))))))
return
''', [(4, '(1)', 3)])
case('04_bad_index_expression', '''// Manual 2.7.2, error 4: "a(2,3)" (the index gives two values) and "a()" (empty index).
int a[4]
function f()
a(2,3)
a()
return
''', [(4, 'a(2', 4), (5, 'a()', 4)])
case('05_bad_variable_type_global', '''// Manual 2.7.2, error 5: "global floa a" (floa is no type).
float a
function f()
global floa a
return
''', [(4, 'floa', 5)])
case('05_bad_variable_type_argument', '''// Manual 2.7.2, error 5: "function func (long a)" (long is no type).
function func (long a)
return
''', [(2, 'long', 5)])
case('06_parentheses_mismatch', '''// Manual 2.7.2, error 6: "b = a(1))" (an unneeded closing parenthesis).
int a[4]
function f()
int b
b = a(1))
return
''', [(5, ')', 6, 1)])
case('07_value_is_expected', '''// Manual 2.7.2, error 7: "b = ^ a" (a value is expected before the ^ operator).
function f()
int a, b
b = ^ a
return
''', [(4, '^', 7)])
case('08_operator_is_expected', '''// Manual 2.7.2, error 8: "b = a c" (c is neither an operator nor a terminator).
function f()
int a, b, c
b = a c
return
''', [(4, 'c', 8)])
case('10_bad_colon_expression_four_values', '''// Manual 2.7.2, error 10: "for k = 10:-1:5:9" (more than three values).
function f()
int k
for k = 10:-1:5:9
end
return
''', [(4, ':9', 10)])
case('10_bad_colon_expression_missing', '''// Manual 2.7.2, error 10: "for k = a" (the colon expression is missing).
function f()
int k, a
for k = a
end
return
''', [(4, 'a', 10)])
case('11_name_is_too_long', '''// Manual 2.7.2, error 11: "int iuyuafdsf_876234" (longer than 12 characters).
int iuyuafdsf_876234
''', [(2, 'iuyuafdsf', 11)])
case('12_no_such_variable', '''// Manual 2.7.2, error 12: "de = sin(0.5)" (de is neither a variable nor a command).
function f()
de = sin(0.5)
return
''', [(3, 'de', 12)])
case('13_too_many_dimensions', '''// Manual 2.7.2, error 13: "int arr[12][2]" (only one-dimensional arrays).
int arr[12][2]
''', [(2, '[2]', 13)])
case('14_bad_number_of_inputs', '''// Manual 2.7.2, error 14: "func(a,2)" calls "function func(float a)" with two inputs.
function main()
float a
func(a,2)
return

function func(float a)
return
''', [(4, 'func', 14)])
case('15_bad_number_of_outputs', '''// Manual 2.7.2, error 15: "a, b = func(1,2)" (several outputs must be in brackets).
function main()
int a, b
a, b = func(1,2)
return

function [int x, int y] = func(int p, int q)
x = p
y = q
return
''', [(4, 'a', 15)])
case('17_too_many_arguments', '''// Manual 2.7.2, error 17: more than 16 input arguments.
function func (int a1, int a2, int a3, int a4, int a5, int a6, int a7, int a8, ...
   int a9, int a10, int a11, int a12, int a13, int a14, int a15, int a16, int a17, ...
   int a18, int a19)
return
''', [(3, 'a17', 17)])
case('22_function_inside_block', '''// Manual 2.7.2, error 22: a function defined inside an if block.
int a
##START
if a<0
a = 0
function func (int a)
end
''', [(6, 'function', 22)])
case('24_name_is_keyword', '''// Manual 2.7.2, error 24: "int switch" (switch is a keyword).
int switch
''', [(2, 'switch', 24)])
case('25_name_is_not_distinct_function', '''// Manual 2.7.2, error 25: a function and a variable with the same name.
int func
function func (int a)
return
''', [(3, 'func (', 25)])
case('25_name_is_not_distinct_local', '''// Manual 2.7.2, error 25: a local with the name of an input argument.
function func (int a)
int a
return
''', [(3, 'a', 25)])
case('26_invalid_name_underscore', '''// Manual 2.7.2, error 26: "int _abc" (a leading underscore).
int _abc
''', [(2, '_abc', 26)])
case('26_invalid_name_function', '''// Manual 2.7.2, error 26: "function (int a)" (the function name is missing).
function (int a)
return
''', [(2, '(', 26)])
case('26_invalid_name_after_comma', '''// Manual 2.7.2, error 26: "int a, b," (the name after the comma is missing).
int a, b,
''', [(2, None, 26)])
case('27_bad_separator', '''// Manual 2.7.2, error 27: "int a b" (the comma between a and b is missing).
int a b
''', [(2, 'b', 27)])
case('28_illegal_global', '''// Manual 2.7.2, error 28: a1 is an int, but the function declares it a float.
int a1
function func (int a)
global float a1
return
''', [(4, 'a1', 28)])
case('29_bad_variable_definition', '''// Manual 2.7.2, error 29: a definition after executable code.
int a1
function func (int a)
int b
global int a1
b = a
float c, d
return
''', [(7, 'float', 29)])
case('30_variable_is_undefined', '''// Manual 2.7.2, error 30: the iteration variable k is not defined. The example's line
// "a = k:" keeps its colon, which is a colon expression outside a for (error 1).
function func (int a)
for k = 1:10
a = k:
end
return
''', [(4, 'k', 30), (5, ':', 1)])
case('32_bad_dimension', '''// Manual 2.7.2, error 32: "int arr[-12]"; manual 2.6: "int z[0]" is illegal too.
int arr[-12]
int z[0]
''', [(2, '[', 32), (3, '[', 32)])
case('33_bad_function_format', '''// Manual 2.7.2, error 33: the definition does not match its prototype.
function func (int a)
function func (float a)
return
''', [(3, 'func (', 33)])
case('34_illegal_minus', '''// Manual 2.7.2, error 34: "[ab] = -func(c)", a minus before a call with several outputs.
function main()
int ab, c
[ab] = -func(c)
return

function [int x, int y] = func(int p)
x = p
y = p
return
''', [(4, '-', 34)])
case('34_illegal_minus_group', '''// Manual 2.7.2, error 34: a minus before parentheses holding several expressions
// (the manual prints "-(2+3), c/5)"; here with its parentheses balanced).
function f()
int b, c
b = -((2+3), c/5)
return
''', [(5, '((', 34)])
case('35_empty_program', '''// Nothing but comments: error 35.
''', [(1, '//', 35)])
case('37_bad_function_call', '''// Manual 2.7.2, error 37: "[a,b,c] - func(x,y) + 5" (no terminator after the outputs).
function main()
int a, b, c, x, y
[a,b,c] - func(x,y) + 5
return

function [int p, int q, int r] = func(int u, int v)
return
''', [(4, '-', 37)])
case('38_expression_is_expected', '''// Manual 2.7.2, error 38: "if a = 0" (an expression is expected after if).
function f()
int a
if a = 0
end
return
''', [(4, '=', 38)])
lines = ['// Manual 2.7.2, error 39: more than 100 nested flow-control blocks.', 'function f()']
lines += ['while 1'] * 101 + ['end'] * 101 + ['return']
case('39_code_is_too_complex', '\n'.join(lines) + '\n', [(103, 'while', 39)])
case('41_case_must_follow_switch', '''// Manual 2.7.2, error 41: "b = 0" between switch and its first case.
function f()
int a, b
switch a
b = 0
case 1, b = 1
end
return
''', [(5, 'b', 41)])
case('42_case_after_otherwise', '''// Manual 2.7.2, error 42: "case 2" after otherwise.
function f()
int a, b
switch a
case 1, b = 1
otherwise
b = 0
case 2, b = 1
end
return
''', [(8, 'case', 42)])
case('43_bad_nesting', '''// Error 43: else without if, an end that closes nothing, a block without end.
function f()
int a
else
end
while a
return
''', [(4, 'else', 43), (5, 'end', 43), (6, 'while', 43), (2, 'f(', 71)])
case('44_code_is_not_expected', '''// Error 44: code on the line of else or end (manual 2.11.1: not on the same line).
function f()
int a, b
if a
b = 1
else b = 2
end b = 3
return
''', [(6, 'b', 44), (7, 'b', 44)])
case('45_bad_flow_control_expression', '''// Manual 2.7.2, error 45: "for k a = 0" (no = after the iteration variable).
function f()
int k, a
for k a = 0
end
return
''', [(4, 'a', 45)])
lines = ['// Error 46: after 30 errors the compiler stops reporting.', '##START']
lines += ['q%d = 1' % i for i in range(32)]
case('46_too_many_errors', '\n'.join(lines) + '\n', [(3 + i, 'q', 12) for i in range(30)] + [(33, 'q', 46)])
case('47_expression_out_of_function', '''// Manual 2.7.2, error 47: code outside any function or label.
int a1
a1 = 0
function func (int a)
return
''', [(3, 'a1', 47)])
case('48_otherwise_without_case', '''// Manual 2.7.2, error 48: otherwise right after switch.
function f()
int a, b
switch a
otherwise
b = 0
end
return
''', [(5, 'otherwise', 48)])
case('49_misplaced_break', '''// Manual 2.7.2, error 49: break inside an if block (the manual writes "If").
function f()
int a
If a < 0
break
end
return
''', [(5, 'break', 49)])
case('50_too_many_outputs', '''// Manual 2.7.2, error 50: two outputs asked of a function that has one.
function main()
int a, c, d
[c,d] = func(a)
return

function [int b] = func (int a)
b = a
return
''', [(4, 'func', 50)])
case('51_line_is_too_long', '''// Error 51: a line of more than 128 characters.
function f()
int a
a = 1 + 2 + 3 + 4 + 5 + 6 + 7 + 8 + 9 + 10 + 11 + 12 + 13 + 14 + 15 + 16 + 17 + 18 + 19 + 20 + 21 + 22 + 23 + 24 + 25 + 26 + 27 + 28 + 29
return
''', [(4, 129, 51)])
case('56_no_such_function', '''// Error 56: goto and reset to names that do not exist.
##START
goto##NOWHERE
reset nothing
''', [(3, 'goto', 56), (4, 'reset', 56)])
case('57_variable_is_array', '''// Manual 2.7.2, error 57: "arr = 0" assigns a whole array.
int arr[10]
##START
arr[1] = 0
arr = 0
''', [(5, 'arr', 57)])
case('58_variable_is_not_array', '''// Manual 2.7.2, error 58: "a1[1] = 0" indexes a scalar.
int a1 // (a scalar)
##START
a1[1] = 0
''', [(4, 'a1', 58)])
case('59_sides_mismatch', '''// Manual 2.7.2, error 59: "[a,b] = 12 + c" (two values on the left, one on the right).
function f()
int a, b, c
[a,b] = 12 + c
return
''', [(4, '12', 59)])
case('60_illegal_local_array', '''// Manual 2.7.2, error 60: a local array.
function func (int a)
int arr[10]
return
''', [(3, 'arr', 60)])
case('61_function_already_has_body', '''// Manual 2.7.2, error 61: func has two bodies. The second body's "end" closes no block
// (error 43).
function func (int a)
wait 2000
return

function func (int a)
until a
end
return
''', [(7, 'func (', 61), (9, 'end', 43)])
case('64_expression_is_not_finished', '''// Manual 2.7.2, error 64: the last line ends with "..." (and so the function has no return, 71).
function f()
float a, b
a = b + 8 / 12 - sin(3.14/2) ...
''', [(4, '...', 64), (2, 'f(', 71)])
case('69_auto_routine_has_argument', '''// Manual 2.7.2, error 69: "function AUTOEXEC (int a)".
function AUTOEXEC (int a)
return
''', [(2, 'AUTOEXEC', 69)])
case('70_label_inside_block', '''// Error 70: a label inside a flow-control block.
int a
##START
while a
##INNER
end
''', [(5, '##INNER', 70)])
case('71_function_without_return', '''// Error 71: a function that does not end with return.
function f()
int a
a = 1

function g()
return
''', [(2, 'f(', 71)])
case('72_block_comment_not_finished', '''// Manual 2.7.2, error 72: the comment block has no end.
function f()
return
/* Just a comment
''', [(4, '/*', 72)])
case('73_bad_function_after_reset', '''// Manual 2.7.2, error 73: "reset func(12)".
function main()
reset func(12)
return

function func(int a)
return
''', [(3, 'func', 73)])
case('74_bad_jump_to_label', '''// Manual 2.7.2, error 74: "goto##func" where func is a function, not a label.
function func ()
return

##START
goto##func
''', [(6, 'goto', 74)])
case('75_illegal_nargout', '''// Manual 2.7.2, error 75: nargout outside a function.
##START
if nargout > 2
end
''', [(3, 'nargout', 75)])
case('76_function_without_body', '''// Error 76: a call of a function that has only a prototype.
function [int y] = half(int x)
function main()
int a
a = half(4)
return
''', [(5, 'half', 76)])
case('77_bad_goto_without_hashes', '''// Manual 2.7.2, error 77: "goto START" (no ## before the name).
##START
goto START
''', [(3, 'START', 77)])
case('77_bad_goto_in_for', '''// Manual 2.7.2, error 77: goto inside a for loop.
int k
##START
for k = 1:10
goto##START
end
''', [(5, 'goto', 77)])
case('78_auto_routine_is_local', '''// Manual 2.7.2, error 78: #@AUTOEXEC inside a function.
function start (int a)
a = 1
#@AUTOEXEC
return
''', [(4, '#@', 78)])
case('79_command_not_program', '''// Manual 2.7.2, error 79: LS is marked "not program".
##START
LS
''', [(3, 'LS', 79)])
case('82_command_not_assign', '''// Manual 2.7.2, error 82: "BG=10" (BG is marked "not assign").
##START
BG=10
''', [(3, 'BG', 82)])
case('84_misplaced_return', '''// Manual 2.7.2, error 84: return inside a try block.
function f()
int a
try
if a > 6
return
end
catch
end
return
''', [(6, 'return', 84)])
case('85_try_and_catch_alone', '''// Manual 2.7.2, error 85: "try, AC=10000000" (code on the try line).
function f()
try, AC=10000000
catch
end
return
''', [(3, ',', 85)])
case('86_division_by_zero', '''// Error 86: a division by the constant zero.
function f()
int a
a = a / 0
return
''', [(4, '0', 86)])
case('91_misplaced_continue', '''// Error 91 (manual 2.11.4): continue outside a loop, and inside a try in a loop.
int a
##START
continue
while a
try
continue
catch
end
end
''', [(4, 'continue', 91), (7, 'continue', 91)])
# The name a diagnostic is about, quoted after the manual's text ("No such variable 'de'"):
# (case, line, code) -> name, each the name the case's line uses.
names = {
    ('04_bad_index_expression', 4, 4): 'a',
    ('04_bad_index_expression', 5, 4): 'a',
    ('05_bad_variable_type_argument', 2, 5): 'long',
    ('05_bad_variable_type_global', 4, 5): 'floa',
    ('11_name_is_too_long', 2, 11): 'iuyuafdsf_876234',
    ('12_no_such_variable', 3, 12): 'de',
    ('13_too_many_dimensions', 2, 13): 'arr',
    ('14_bad_number_of_inputs', 4, 14): 'func',
    ('24_name_is_keyword', 2, 24): 'switch',
    ('25_name_is_not_distinct_function', 3, 25): 'func',
    ('25_name_is_not_distinct_local', 3, 25): 'a',
    ('26_invalid_name_underscore', 2, 26): '_abc',
    ('28_illegal_global', 4, 28): 'a1',
    ('30_variable_is_undefined', 4, 30): 'k',
    ('32_bad_dimension', 2, 32): 'arr',
    ('32_bad_dimension', 3, 32): 'z',
    ('33_bad_function_format', 3, 33): 'func',
    ('43_bad_nesting', 2, 71): 'f',
    ('50_too_many_outputs', 4, 50): 'func',
    ('56_no_such_function', 3, 56): 'NOWHERE',
    ('56_no_such_function', 4, 56): 'nothing',
    ('57_variable_is_array', 5, 57): 'arr',
    ('58_variable_is_not_array', 4, 58): 'a1',
    ('60_illegal_local_array', 3, 60): 'arr',
    ('61_function_already_has_body', 7, 61): 'func',
    ('64_expression_is_not_finished', 2, 71): 'f',
    ('69_auto_routine_has_argument', 2, 69): 'AUTOEXEC',
    ('70_label_inside_block', 5, 70): 'INNER',
    ('71_function_without_return', 2, 71): 'f',
    ('73_bad_function_after_reset', 3, 73): 'func',
    ('74_bad_jump_to_label', 6, 74): 'func',
    ('76_function_without_body', 5, 76): 'half',
    ('77_bad_goto_in_for', 5, 77): 'START',
    ('77_bad_goto_without_hashes', 3, 77): 'START',
    ('78_auto_routine_is_local', 4, 78): 'AUTOEXEC',
    ('79_command_not_program', 3, 79): 'LS',
    ('82_command_not_assign', 3, 82): 'BG',
}
names.update({('46_too_many_errors', 3 + i, 12): 'q%d' % i for i in range(30)})
for name, (src, expect) in cases.items():
    lines = src.split('\n')
    out = []
    for item in expect:
        line, anchor, code = item[0], item[1], item[2]
        nth = item[3] if len(item) > 3 else 0
        text = lines[line - 1]
        if anchor is None: col = len(text) + 1
        elif isinstance(anchor, int): col = anchor
        else:
            pos = -1
            for _ in range(nth + 1): pos = text.index(anchor, pos + 1)
            col = pos + 1
        out.append((line, col, code))
    out.sort()
    with open(name + '.gold', 'w') as f: f.write(src)
    with open(name + '.expected', 'w') as f:
        for line, col, code in out:
            named = " '%s'" % names[(name, line, code)] if (name, line, code) in names else ''
            f.write('%s.gold:%d:%d: error: %s%s [gold %d]\n' % (name, line, col, texts[code], named, code))
print(len(cases), 'cases')
