/** The general method library: the parameter rules its params records share. Methods live in the sub-packages by layer. */
package org.habla.methods;
