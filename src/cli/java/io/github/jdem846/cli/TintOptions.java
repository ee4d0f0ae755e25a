package io.github.jdem846.cli;

import io.github.jdem846.tint.ColorRamp;
import io.github.jdem846.tint.ColorSelection;
import io.github.jdem846.tint.TintScale;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Iterator;
import java.util.Locale;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;
import picocli.CommandLine.Spec;

/** {@code --tint NAME|FILE} with gdaldem's {@code --exact-color}/{@code --nearest-color}. */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
public final class TintOptions {

    @Spec(Spec.Target.MIXEE)
    CommandSpec command;

    @Option(names = "--tint", paramLabel = "NAME|FILE", defaultValue = ColorRamp.DEFAULT_NAME,
            description = "Colour ramp: a built-in name (hypsometric, hypsometric-natural, bathymetric, etopo1, "
                    + "standard, dark-bathymetric, tri-green-yellow-red, gray, green, black, bumpmap, …), a gdaldem "
                    + "colour file, or 'none'. Default: ${DEFAULT-VALUE}: the "
                    + "article's table 2 (hypsometric), split at 0 m with the bathymetric ramp below when the DEM "
                    + "holds both land and sea.")
    String tint;

    @Option(names = {"--exact-color", "--exact_color_entry", "-exact_color_entry"},
            description = "Colour file: only values equal to an entry get its colour (gdaldem -exact_color_entry).")
    boolean exact;

    @Option(names = {"--nearest-color", "--nearest_color_entry", "-nearest_color_entry"},
            description = "Colour file: the nearest entry's colour, no interpolation (gdaldem -nearest_color_entry).")
    boolean nearest;

    @Option(names = "--tint-scale", paramLabel = "SCALE", defaultValue = "linear", converter = ScaleName.class,
            completionCandidates = ScaleName.class,
            description = "How a percent ramp spreads the DEM's range over its colours (the original's elevation "
                    + "scalers): linear, logarithmic, exponential or cubic; logarithmic gives low ground more colours, exponential and "
                    + "cubic high ground. Default: ${DEFAULT-VALUE}.")
    TintScale scale;

    /**
     * Uses {@code nameOrFile}, given in the colour file's place of {@code tint IN COLORFILE OUT}, as
     * {@code --tint}.
     *
     * @throws picocli.CommandLine.ParameterException when {@code --tint} was given too
     */
    void usePositional(String nameOrFile) {
        if (command.commandLine().getParseResult().hasMatchedOption("--tint")) {
            throw Usage.error(command, "two colour ramps: '" + nameOrFile + "' in the colour file's place (tint IN "
                    + "COLORFILE OUT) and --tint " + tint + "; give one");
        }
        tint = nameOrFile;
    }

    /**
     * The ramp, or {@code null} for 'none'. An unknown name or flags that do not apply are bad usage; a colour file
     * that cannot be read is an input error.
     */
    ColorRamp ramp() throws IOException {
        ColorRamp ramp = unscaledRamp();
        if (ramp == null || scale == TintScale.LINEAR) {
            return ramp;
        }
        try {
            return ramp.withScale(scale);
        } catch (IllegalArgumentException e) {
            throw Usage.invalid(command, e.getMessage() + " (drop --tint-scale, or choose such a ramp)",
                    "--tint-scale");
        }
    }

    private ColorRamp unscaledRamp() throws IOException {
        if (exact && nearest) {
            throw Usage.error(command, "give --exact-color or --nearest-color, not both");
        }
        if (tint.toLowerCase(Locale.ROOT).equals("none")) {
            return null;
        }
        Path file = Path.of(tint);
        if (Files.isRegularFile(file)) {
            ColorSelection mode = exact ? ColorSelection.EXACT : nearest ? ColorSelection.NEAREST
                    : ColorSelection.INTERPOLATE;
            return ColorRamp.fromGdalColorFile(file, mode);
        }
        if (exact || nearest) {
            throw Usage.error(command, "--exact-color and --nearest-color apply to colour files; '" + tint
                    + "' is not a file");
        }
        if (tint.contains("/") || tint.contains("\\") || tint.contains(".")) {
            throw new IllegalArgumentException("colour file '" + tint + "' does not exist (built-in ramps: "
                    + String.join(", ", ColorRamp.names()) + ")");
        }
        try {
            return ColorRamp.named(tint);
        } catch (IllegalArgumentException e) {
            throw Usage.invalid(command, e.getMessage(), "--tint");
        }
    }

    /** {@code --tint-scale}'s names, in any case, whatever the command line's enum setting (tiles runs alone too). */
    static final class ScaleName implements ITypeConverter<TintScale>, Iterable<String> {
        @Override
        public TintScale convert(String value) {
            for (TintScale scale : TintScale.values()) {
                if (scale.name().equalsIgnoreCase(value.strip())) {
                    return scale;
                }
            }
            throw new TypeConversionException("'" + value + "' is not a tint scale: give linear, logarithmic, "
                    + "exponential or cubic");
        }

        @Override
        public Iterator<String> iterator() {
            return Arrays.stream(TintScale.values()).map(s -> s.name().toLowerCase(Locale.ROOT)).iterator();
        }
    }
}
