/** Built-in methods: the trivial pass-through methods every config can use, and a provider base for method types. */
package org.habla.method.builtin;
