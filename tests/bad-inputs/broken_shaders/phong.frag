void main() { undefined_thing; }
void other() { also_undefined; }
