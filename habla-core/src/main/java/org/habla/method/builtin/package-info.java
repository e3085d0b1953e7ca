/** Built-in methods: the trivial pass-through and channel-reader methods every config can use. */
package org.habla.method.builtin;
