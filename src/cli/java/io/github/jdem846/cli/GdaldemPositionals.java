package io.github.jdem846.cli;

import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import picocli.CommandLine.IModelTransformer;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;

/**
 * gdaldem's positional forms, {@code hillshade IN OUT} and {@code tint IN COLORFILE OUT} (color-relief's order),
 * beside {@code -o}. With {@code -o} every FILE is an input, as always. Without it the last FILE is the output and,
 * for tint, the one before it the colour ramp (what {@code --tint} takes: a colour file or a built-in name); the
 * FILE arguments before those are the inputs, several of them a mosaic. What cannot be meant as such is bad usage:
 * too few FILE arguments, an output that is an existing DEM file, a directory or a glob (an input forgotten
 * {@code -o}), a DEM file in the colour file's place.
 */
final class GdaldemPositionals {

    /** Extensions of files taken for DEMs (never overwritten as an output named without {@code -o}). */
    private static final Set<String> DEM_FILES = Set.of("tif", "tiff", "gtif", "flt", "bil", "hgt", "asc", "vrt",
            "hdr");

    /**
     * The arguments of a command split into its parts.
     *
     * @param inputs the DEM files, directories or globs (empty: the bundled sample)
     * @param ramp   tint's colour file or ramp name given positionally, or null
     * @param output the picture to write
     */
    record Split(List<String> inputs, String ramp, Path output) {
    }

    private GdaldemPositionals() {
    }

    /**
     * Splits the FILE arguments of {@code hillshade} or {@code tint}.
     *
     * @param spec     the command, for its name and usage errors
     * @param files    the FILE arguments, possibly null
     * @param output   {@code -o}, or null when absent
     * @param withRamp true for tint (IN COLORFILE OUT)
     * @throws picocli.CommandLine.ParameterException when the arguments do not make one of the forms
     */
    static Split split(CommandSpec spec, List<String> files, Path output, boolean withRamp) {
        List<String> args = files == null ? List.of() : files;
        if (output != null) {
            return new Split(args, null, output);
        }
        String name = spec.name();
        String form = withRamp ? name + " IN COLORFILE OUT" : name + " IN OUT";
        int trailing = withRamp ? 2 : 1;
        if (args.isEmpty()) {
            throw Usage.error(spec, "missing the output: give -o OUT (the bundled sample is drawn without FILE), or "
                    + "'jdem846 " + form + "'");
        }
        if (args.size() <= trailing) {
            throw Usage.error(spec, "without -o, " + name + " takes " + (withRamp
                    ? "IN... COLORFILE OUT (gdaldem color-relief's order)" : "IN... OUT (gdaldem's order)")
                    + "; got " + count(args.size()) + " (" + String.join(", ", args) + "): " + (withRamp
                    ? "give the colour file or a ramp name before the output" : "name the output last")
                    + ", or give the output with -o OUT");
        }
        String out = args.get(args.size() - 1);
        requireNewOutput(spec, out, form);
        String ramp = null;
        if (withRamp) {
            ramp = args.get(args.size() - 2);
            if (isDem(ramp) || isDirectory(ramp)) {
                throw Usage.error(spec, "'" + ramp + "' is in the colour file's place ('jdem846 " + form
                        + "') but is a DEM " + (isDirectory(ramp) ? "directory" : "file")
                        + "; for several DEM files give -o OUT and the ramp with --tint");
            }
        }
        return new Split(List.copyOf(args.subList(0, args.size() - trailing)), ramp, Path.of(out));
    }

    /** Refuses, as the output, what can only be an input: it would be overwritten, or cannot be written. */
    private static void requireNewOutput(CommandSpec spec, String out, String form) {
        String why = null;
        if (isDirectory(out)) {
            why = "is a directory";
        } else if (isDem(out) && Files.isRegularFile(Path.of(out))) {
            why = "is an existing DEM file, which would be overwritten";
        } else if (!exists(out) && out.matches(".*[*?\\[{].*")) {
            why = "is a glob pattern";
        }
        if (why != null) {
            throw Usage.error(spec, "'" + out + "' " + why + ": without -o the last FILE is the output ('jdem846 "
                    + form + "'); name a new image file (.png, .tif), or give the output with -o OUT");
        }
    }

    private static boolean isDem(String arg) {
        Path p = pathOrNull(arg);
        return p != null && DEM_FILES.contains(InputPaths.extension(p));
    }

    private static boolean exists(String arg) {
        Path p = pathOrNull(arg);
        return p != null && Files.exists(p);
    }

    private static boolean isDirectory(String arg) {
        Path p = pathOrNull(arg);
        return p != null && Files.isDirectory(p);
    }

    /** The path named, or null for text that is not a path here. */
    private static Path pathOrNull(String arg) {
        try {
            return Path.of(arg);
        } catch (InvalidPathException e) {
            return null;
        }
    }

    private static String count(int n) {
        return n == 1 ? "1 FILE" : n + " FILEs";
    }

    /**
     * Applied by picocli to {@code hillshade} and {@code tint} once their model is built: {@code -o} becomes
     * optional (the usage says {@code [-o=OUT]}), and FILE's description says what the last FILE arguments are
     * without it.
     */
    static final class Transformer implements IModelTransformer {
        @Override
        public CommandSpec transform(CommandSpec spec) {
            // picocli has no way to change an option in place: every option is taken out and put back in its
            // order (the usage lists them as declared), -o as an optional copy of itself.
            List<OptionSpec> options = List.copyOf(spec.options());
            options.forEach(spec::remove);
            for (OptionSpec o : options) {
                spec.addOption(o.longestName().equals("--output") ? OptionSpec.builder(o).required(false).build() : o);
            }
            PositionalParamSpec files = spec.positionalParameters().get(0);
            spec.remove(files);
            String positional = spec.name().equals("tint")
                    ? " Without -o, gdaldem color-relief's order: IN... COLORFILE OUT, the colour file (or a"
                    + " built-in ramp name, as --tint takes) and the output last."
                    : " Without -o, gdaldem's order: IN... OUT, the output last.";
            spec.addPositional(PositionalParamSpec.builder(files)
                    .description(files.description()[0] + positional).build());
            return spec;
        }
    }
}
