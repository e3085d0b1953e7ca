/** Plugins: the provider interfaces for method and driver types, and the registry that discovers them. */
package org.habla.plugin;
