package io.github.jdem846.cli;

import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.util.Locale;

/**
 * The command line's names of the library's hillshade methods ({@code jdem846}, {@code horn}, {@code
 * multidirectional}) and cast-shadow algorithms ({@code march}, {@code sweep}, {@code exact}, {@code none}), kept
 * here so the core enums carry no CLI spelling.
 */
final class MethodNames {

    private MethodNames() {
    }

    /** The command-line name of {@code method}: its constant's name in lower case. */
    static String of(HillshadeMethod method) {
        return method.name().toLowerCase(Locale.ROOT);
    }

    /** The command-line name of {@code algorithm}: its constant's name in lower case. */
    static String of(ShadowAlgorithm algorithm) {
        return algorithm.name().toLowerCase(Locale.ROOT);
    }

    /** The method named {@code name} (case-insensitive), with a message listing the choices otherwise. */
    static HillshadeMethod hillshade(String name) {
        for (HillshadeMethod m : HillshadeMethod.values()) {
            if (of(m).equalsIgnoreCase(name == null ? "" : name.trim())) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown hillshade method '" + name
                + "'; choose jdem846 (default), horn or multidirectional");
    }

    /** The shadow algorithm named {@code name} (case-insensitive), with a message listing the choices otherwise. */
    static ShadowAlgorithm shadows(String name) {
        for (ShadowAlgorithm a : ShadowAlgorithm.values()) {
            if (of(a).equalsIgnoreCase(name == null ? "" : name.trim())) {
                return a;
            }
        }
        throw new IllegalArgumentException("unknown shadow algorithm '" + name
                + "'; expected one of march, sweep, exact, none");
    }
}
