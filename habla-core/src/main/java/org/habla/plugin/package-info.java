/**
 * Plugins: the provider interfaces for method and driver types, {@link org.habla.plugin.SimpleMethodProvider}
 * (a method type's provider in one constructor call), and the registry that discovers them.
 */
package org.habla.plugin;
