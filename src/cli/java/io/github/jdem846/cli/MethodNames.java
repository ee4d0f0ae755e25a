package io.github.jdem846.cli;

import io.github.jdem846.render.LightModel;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.util.Locale;

/**
 * The command line's names of the library's hillshade methods ({@code jdem846}, {@code horn}, {@code
 * multidirectional}, {@code combined}, {@code igor}) and cast-shadow algorithms ({@code march}, {@code sweep},
 * {@code exact}, {@code none}), kept here so the core enums carry no CLI spelling.
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
        return named(HillshadeMethod.values(), name, "unknown hillshade method '" + name
                + "'; choose jdem846 (default), horn, multidirectional, combined or igor");
    }

    /** The shadow algorithm named {@code name} (case-insensitive), with a message listing the choices otherwise. */
    static ShadowAlgorithm shadows(String name) {
        return named(ShadowAlgorithm.values(), name, "unknown shadow algorithm '" + name
                + "'; expected one of march, sweep, exact, none");
    }

    static LightModel lightModel(String name) {
        return named(LightModel.values(), name, "unknown light model '" + name + "'; expected one of sky, jdem846");
    }

    /** The constant of {@code values} whose lower-case name is {@code name} (case-insensitive, trimmed). */
    private static <E extends Enum<E>> E named(E[] values, String name, String unknown) {
        String wanted = name == null ? "" : name.trim();
        for (E e : values) {
            if (e.name().equalsIgnoreCase(wanted)) {
                return e;
            }
        }
        throw new IllegalArgumentException(unknown);
    }
}
