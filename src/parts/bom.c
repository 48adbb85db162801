/* bom.c — the chosen parts, the bill of materials they make and the
 * rationale lines that say why (see parts.h). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "parts/parts_int.h"
#include "sizing/perf.h"
#include "util/strbuf.h"
#include "util/units.h"

/* Append a formatted piece to dst[n]. */
static void __attribute__((format(printf, 3, 4)))
append(char *dst, size_t n, const char *fmt, ...)
{
	size_t len = strlen(dst);
	if (len + 1 >= n)
		return;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(dst + len, n - len, fmt, ap);
	va_end(ap);
}

/* The first web address in a catalogue source note, for the buyer: up to
 * the first blank or ";", "http" or "www" at its start. */
static void
source_url(const char *source, char *out, size_t n)
{
	out[0] = '\0';
	const char *u = strstr(source, "http");
	if (u == NULL)
		u = strstr(source, "www.");
	if (u == NULL)
		return;
	size_t len = strcspn(u, " ;|,\"");
	while (len > 0 && (u[len - 1] == '.' || u[len - 1] == ')'))
		len--;
	if (len >= n)
		return; /* a cut address is worse than none */
	memcpy(out, u, len);
	out[len] = '\0';
}

/* An ESC board's `carries` list in words: "flight controller, receiver
 * and video transmitter". */
static const char *
on_board_text(const char *carries, char *buf, size_t size)
{
	static const struct { const char *kind, *words; } names[] = {
		{ "flight_controller", "flight controller" },
		{ "receiver", "receiver" },
		{ "video_tx", "video transmitter" },
	};
	const char *have[3];
	int n = 0;
	for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
		if (catalog_list_names(carries, names[i].kind))
			have[n++] = names[i].words;
	buf[0] = '\0';
	for (int i = 0; i < n; i++)
		append(buf, size, "%s%s", i == 0 ? "" : i == n - 1 ? " and " : ", ",
		    have[i]);
	return buf;
}

static void
part_common(struct res_part *rp, const char *id, const char *manufacturer,
            const char *part_number, double price_usd, const char *price_date,
            const char *source)
{
	memset(rp, 0, sizeof *rp);
	rp->chosen = true;
	str_copy(rp->id, sizeof rp->id, id);
	str_copy(rp->manufacturer, sizeof rp->manufacturer, manufacturer);
	str_copy(rp->part_number, sizeof rp->part_number, part_number);
	rp->unit_price_usd = price_usd > 0.0 ? price_usd : 0.0;
	str_copy(rp->price_date, sizeof rp->price_date, price_date);
	source_url(source, rp->source_url, sizeof rp->source_url);
}

/* r->motor/prop/battery/esc from the design of record. */
static void
fill_parts(const struct parts_ctx *x, const struct parts_closed *c,
           struct solve_result *r)
{
	int n = x->p->n_rotors;
	const struct catalog_motor *m = c->o.motor;
	struct res_part *rp = &r->motor;
	part_common(rp, m->id, m->manufacturer, m->part_number, m->price_usd,
	    m->price_date, m->source);
	if (m->integrated)
		append(rp->description, sizeof rp->description, "integrated motor + "
		    "ESC + %.0f in propeller, ", m->integrated_prop_in);
	append(rp->description, sizeof rp->description, "%.0f KV, %.0f g, %.0f A max",
	    m->kv_rpm_per_v, m->mass_kg * 1000.0, m->max_current_a);
	if (m->cells_min > 0 && m->cells_max > 0)
		append(rp->description, sizeof rp->description, ", %d-%dS",
		    m->cells_min, m->cells_max);
	rp->qty = n;
	rp->unit_mass_kg = m->mass_kg;
	rp->j_score = c->o.j;

	memset(&r->prop, 0, sizeof r->prop);
	memset(&r->esc, 0, sizeof r->esc);
	if (c->o.prop != NULL) {
		const struct catalog_prop *p = c->o.prop;
		rp = &r->prop;
		part_common(rp, p->id, p->manufacturer, p->part_number, p->price_usd,
		    p->price_date, p->source);
		append(rp->description, sizeof rp->description, "%.1f x %.1f in",
		    p->diameter_in, p->pitch_in);
		if (p->blades > 0)
			append(rp->description, sizeof rp->description, ", %d-blade", p->blades);
		if (p->material[0])
			append(rp->description, sizeof rp->description, ", %s", p->material);
		if (p->folding == 1)
			append(rp->description, sizeof rp->description, ", folding");
		rp->qty = n;
		rp->unit_mass_kg = p->mass_kg;
		rp->j_score = c->o.j;
	}
	if (c->esc != NULL) {
		const struct catalog_esc *e = c->esc;
		rp = &r->esc;
		part_common(rp, e->id, e->manufacturer, e->part_number, e->price_usd,
		    e->price_date, e->source);
		append(rp->description, sizeof rp->description, "%.0f A continuous",
		    e->continuous_current_a);
		if (e->burst_current_a > 0.0)
			append(rp->description, sizeof rp->description, ", %.0f A burst",
			    e->burst_current_a);
		if (e->channels == 4)
			append(rp->description, sizeof rp->description, ", 4-in-1");
		if (e->cells_max > 0)
			append(rp->description, sizeof rp->description, ", up to %dS", e->cells_max);
		/* An all-in-one board: what the kit then does not buy apart. */
		char on_board[96];
		if (c->kit.n_on_esc > 0)
			append(rp->description, sizeof rp->description, "; carries the %s",
			    on_board_text(e->carries, on_board, sizeof on_board));
		rp->qty = c->n_esc;
		rp->unit_mass_kg = e->mass_kg;
	}
	const struct catalog_battery *b = c->pack.b;
	rp = &r->battery;
	part_common(rp, b->id, b->manufacturer, b->part_number, b->price_usd,
	    b->price_date, b->source);
	append(rp->description, sizeof rp->description, "%s %dS %.0f mAh, %.0fC "
	    "continuous", b->chemistry, b->cells_series, b->capacity_ah * 1000.0,
	    b->continuous_c);
	if (c->pack.series * c->pack.parallel > 1)
		append(rp->description, sizeof rp->description, "; %d in series x %d "
		    "in parallel for %dS %.0f mAh", c->pack.series, c->pack.parallel,
		    c->o.cells, c->pack.capacity_ah * 1000.0);
	rp->qty = c->pack.series * c->pack.parallel;
	rp->unit_mass_kg = b->mass_kg;
	r->battery_series_packs = c->pack.series;
	r->battery_parallel_packs = c->pack.parallel;
}

static struct res_bom_line *
bom_add(struct solve_result *r, int qty, const char *category,
        const char *manufacturer, const char *part_number,
        const char *description, double unit_kg, double unit_usd,
        const char *id)
{
	if (r->n_bom >= RES_MAX_BOM || qty <= 0)
		return NULL;
	struct res_bom_line *b = &r->bom[r->n_bom];
	memset(b, 0, sizeof *b);
	b->item = ++r->n_bom;
	b->qty = qty;
	str_copy(b->category, sizeof b->category, category);
	str_copy(b->manufacturer, sizeof b->manufacturer, manufacturer);
	str_copy(b->part_number, sizeof b->part_number, part_number);
	str_copy(b->description, sizeof b->description, description);
	b->unit_mass_kg = unit_kg;
	b->total_mass_kg = unit_kg * (double)qty;
	b->unit_price_usd = unit_usd > 0.0 ? unit_usd : 0.0;
	b->total_price_usd = b->unit_price_usd * (double)qty;
	str_copy(b->catalogue_id, sizeof b->catalogue_id, id);
	return b;
}

static void
bom_part(struct solve_result *r, const struct res_part *p, int qty,
         const char *category, const char *part_number, const char *note)
{
	if (!p->chosen)
		return;
	char d[160];
	snprintf(d, sizeof d, "%s%s", p->description, note);
	struct res_bom_line *b = bom_add(r, qty, category, p->manufacturer,
	    part_number, d, p->unit_mass_kg, p->unit_price_usd, p->id);
	if (b != NULL) {
		str_copy(b->price_date, sizeof b->price_date, p->price_date);
		str_copy(b->source_url, sizeof b->source_url, p->source_url);
	}
}

/* A catalogue part that is not one of the four chosen ones (frame kit,
 * avionics, connectors), with its price date and maker's page. */
static void
bom_catalogue(struct solve_result *r, int qty, const char *category,
              const char *id, const char *manufacturer,
              const char *part_number, const char *description, double unit_kg,
              double unit_usd, const char *price_date, const char *source)
{
	struct res_bom_line *b = bom_add(r, qty, category, manufacturer,
	    part_number, description, unit_kg, unit_usd, id);
	if (b == NULL)
		return;
	if (unit_usd > 0.0)
		str_copy(b->price_date, sizeof b->price_date, price_date);
	source_url(source, b->source_url, sizeof b->source_url);
}

/* A sized part the catalogue cannot supply (mass from the design of
 * record): made to the dimensions the description gives. */
static void
bom_custom(struct solve_result *r, int qty, const char *part_number,
           const char *description, double total_kg)
{
	if (total_kg > 0.0)
		bom_add(r, qty, "custom", "custom", part_number, description,
		    total_kg / (double)qty, 0.0, "");
}

/* The battery connectors' line: the part number names the connector, the
 * description says how it meets the pack and what each pack carries. */
static void
bom_connector(const struct parts_closed *c, struct solve_result *r)
{
	const struct parts_kit *kit = &c->kit;
	const struct res_run *o = &r->closed;
	if (kit->connector == NULL)
		return;
	const char *plug = c->pack.b->connector;
	double share = 1.0 / (double)c->pack.parallel;
	char carries[80], d[256];
	snprintf(carries, sizeof carries, "%.0f A sustained, %.0f A at full "
	    "throttle", kit->load.sustained_a * share, o->peak_current_a * share);
	if (kit->connector_mates)
		snprintf(d, sizeof d, "1 per pack, the mate of its %s plug; each pack "
		    "%s", plug, carries);
	else if (kit->plug != NULL)
		snprintf(d, sizeof d, "1 per pack, fitted in place of its %s plug, "
		    "whose mate the catalogue cannot weigh; each pack %s", plug,
		    carries);
	else if (strcasecmp(plug, "smart") == 0)
		snprintf(d, sizeof d, "1 per pack, joining the harness to the smart "
		    "pack's own lead; each pack %s", carries);
	else
		snprintf(d, sizeof d, "1 per pack, fitted to it (its plug is not "
		    "published); each pack %s", carries);
	bom_catalogue(r, kit->n_connectors, "connector", kit->connector->id,
	    kit->connector->manufacturer, kit->connector->part_number, d,
	    kit->connector->mass_kg, kit->connector->price_usd,
	    kit->connector->price_date, kit->connector->source);
}

/* One harness run in words: "main lead 8 AWG, 55 mm". */
static void
run_text(const char *name, const struct parts_run *run, char *buf, size_t n)
{
	if (run->awg == NULL)
		return;
	append(buf, n, "%s%s", buf[0] != '\0' && buf[strlen(buf) - 1] != ' '
	    ? "; " : "", name);
	if (run->n_runs > 1)
		append(buf, n, " x%d", run->n_runs);
	append(buf, n, " %s AWG", run->awg);
	if (run->parallel > 1)
		append(buf, n, " x%d", run->parallel);
	append(buf, n, ", %.0f mm", run->length_m * 1000.0);
}

/* The power harness line's description (harness.c sizes it). */
static void
harness_text(const struct parts_kit *kit, char *d, size_t n)
{
	snprintf(d, n, "Copper for %.0f A at full throttle (chassis-wiring "
	    "ampacity): ", kit->load.full_a);
	run_text("main lead", &kit->harness_main, d, n);
	run_text("pack leads", &kit->harness_pack, d, n);
	run_text("arm runs", &kit->harness_arm, d, n);
}

/* The role's hardware line: what the role carries besides its payload,
 * less what the class's items supply (the agricultural pump). */
static void
role_line(const struct parts_ctx *x, const struct parts_kit *kit,
          double role_kg, struct solve_result *r)
{
	static const char *const words[ROLE_MAX] = {
		[ROLE_IMAGING] = "gimbal mount and dampers",
		[ROLE_DELIVERY] = "release mechanism and payload mounts",
		[ROLE_AGRICULTURE] = "tank mounts, plumbing, booms and nozzles",
		[ROLE_INSPECTION] = "payload mounts",
		[ROLE_MAPPING] = "payload mounts",
	};
	int role = x->spec->payload_role.type;
	const char *what = role >= 0 && role < ROLE_MAX && words[role] != NULL
	    ? words[role] : "payload mounts";
	char d[160];
	snprintf(d, sizeof d, "Role hardware: %s (the role's allowance%s%s%s)",
	    what, kit->role_supplied_what != NULL ? ", less the " : "",
	    kit->role_supplied_what != NULL ? kit->role_supplied_what : "",
	    kit->role_supplied_what != NULL ? " listed apart" : "");
	bom_custom(r, 1, "Role hardware", d, role_kg);
}

/* The bill of materials: catalogue parts (propellers in their two turning
 * directions), the sized custom parts, then the payload the customer
 * furnishes.  The parts sum, with the payload, to the takeoff mass of
 * record. */
static void
fill_bom(const struct parts_ctx *x, const struct parts_closed *c,
         struct solve_result *r)
{
	const struct sizing_params *p = x->p;
	const struct res_run *o = &r->closed;
	const struct res_mass *m = &o->mass;
	char d[160];
	r->n_bom = 0;
	bom_part(r, &r->motor, r->motor.qty, "motor", r->motor.part_number, "");
	if (r->prop.chosen) {
		/* Half turn each way; a maker sells the counter-rotating blade
		 * under its own SKU or as the pair under one. */
		int cw = (r->prop.qty + 1) / 2, ccw = r->prop.qty - cw;
		bom_part(r, &r->prop, cw, "propeller", r->prop.part_number,
		    ", CW (normal)");
		char ccw_pn[sizeof r->prop.part_number + 8];
		snprintf(ccw_pn, sizeof ccw_pn, "%s%s", r->prop.part_number,
		    c->o.prop->part_number_ccw[0] ? "" : " (CCW)");
		bom_part(r, &r->prop, ccw, "propeller",
		    c->o.prop->part_number_ccw[0] ? c->o.prop->part_number_ccw : ccw_pn,
		    ", CCW (pusher)");
	}
	bom_part(r, &r->battery, r->battery.qty, "battery", r->battery.part_number, "");
	double cells_kg = (double)r->battery.qty * r->battery.unit_mass_kg;
	if (c->pack.mass_kg > cells_kg) {
		snprintf(d, sizeof d, "Pack hardware for %d single cells (holders, "
		    "nickel strip, balance wiring, wrap): 12 %% of the cells",
		    r->battery.qty);
		bom_custom(r, 1, "Pack hardware", d, c->pack.mass_kg - cells_kg);
	}
	bom_part(r, &r->esc, r->esc.qty, "esc", r->esc.part_number, "");
	const struct parts_kit *kit = &c->kit;
	bom_connector(c, r);
	/* The leads that wire the packs into the bus: banks of packs in
	 * parallel, joined in series; their copper is the harness's pack
	 * leads (harness.c). */
	if (c->pack.series > 1 && c->pack.parallel > 1) {
		snprintf(d, sizeof d, "Series-parallel lead: %d banks of %d packs in "
		    "parallel, joined in series into %dS, for %.0f A at full "
		    "throttle (its copper is in the power harness)", c->pack.series,
		    c->pack.parallel, c->o.cells, o->peak_current_a);
		bom_add(r, 1, "custom", "custom", "Series-parallel lead", d, 0.0,
		    0.0, "");
	} else if (c->pack.series > 1) {
		snprintf(d, sizeof d, "Series lead joining %d packs into %dS, for "
		    "%.0f A at full throttle (its copper is in the power harness)",
		    c->pack.series, c->o.cells, o->peak_current_a);
		bom_add(r, 1, "custom", "custom", "Series lead", d, 0.0, 0.0, "");
	} else if (c->pack.parallel > 1) {
		snprintf(d, sizeof d, "Parallel lead joining %d packs, for %.0f A at "
		    "full throttle (its copper is in the power harness)",
		    c->pack.parallel, o->peak_current_a);
		bom_add(r, 1, "custom", "custom", "Parallel lead", d, 0.0, 0.0, "");
	}
	int arms = p->coaxial ? p->n_rotors / 2 : p->n_rotors;
	if (kit->frame != NULL) {
		const struct catalog_frame *f = kit->frame;
		snprintf(d, sizeof d, "Frame kit, %d rotors on %.0f mm wheelbase: %s",
		    f->rotor_count, f->wheelbase_m * 1000.0, f->includes);
		bom_catalogue(r, 1, "frame", f->id, f->manufacturer,
		    f->part_number, d, f->mass_kg, f->price_usd, f->price_date,
		    f->source);
	} else {
		snprintf(d, sizeof d, "CFRP arm tube OD %.1f x wall %.2f x length "
		    "%.0f mm, cut to length (no catalogue frame kit fits)",
		    o->arm_outer_diameter_mm, o->arm_wall_thickness_mm,
		    o->arm_length_m * 1000.0);
		bom_custom(r, arms > 0 ? arms : 1, "Carbon arm", d, m->arm_kg);
		bom_custom(r, 1, "Centre frame", "Centre plates and spar joints",
		    m->frame_kg);
	}
	double screws_kg = parts_kit_fastener_kg(kit);
	bom_custom(r, 1, "Body and landing gear", "Body shell, landing gear and mounts",
	    m->other_kg - screws_kg);
	int n_screws = parts_kit_screws(kit);
	snprintf(d, sizeof d, "Steel socket-head cap screws %s, DIN 912: %d a motor"
	    "%s (count and size an estimate)", kit->fastener_size,
	    kit->n_motor_screws / (p->n_rotors > 0 ? p->n_rotors : 1),
	    kit->frame != NULL ? "" : ", 4 an arm");
	bom_custom(r, n_screws > 0 ? n_screws : 1, "Fasteners", d, screws_kg);
	harness_text(kit, d, sizeof d);
	bom_custom(r, 1, "Power harness", d, m->wiring_kg - kit->connector_kg);
	for (int i = 0; i < kit->n_part; i++) {
		const struct catalog_avionics *a = kit->part[i];
		bom_catalogue(r, 1, "avionics", a->id, a->manufacturer,
		    a->part_number, a->description, a->mass_kg, a->price_usd,
		    a->price_date, a->source);
	}
	for (int i = 0; i < kit->n_allowance; i++) {
		if (kit->allowance_basis[i] != NULL)
			snprintf(d, sizeof d, "%s: allowance, %s", kit->allowance_what[i],
			    kit->allowance_basis[i]);
		else
			snprintf(d, sizeof d, "%s: allowance of the airframe class (no "
			    "catalogue part)", kit->allowance_what[i]);
		bom_custom(r, 1, kit->allowance_what[i], d, kit->allowance_kg[i]);
	}
	if (kit->remote_id_missing)
		bom_add(r, 1, "custom", "custom", "Remote ID module", "Required (EU "
		    "class C1 and up, US Part 89: 250 g and more); no catalogue "
		    "module fits: choose one and add its mass", 0.0, 0.0, "");
	role_line(x, kit, m->role_aux_kg, r);
	r->bom_mass_kg = 0.0;
	r->bom_price_usd = 0.0;
	r->bom_priced_lines = 0;
	for (int i = 0; i < r->n_bom; i++) {
		r->bom_mass_kg += r->bom[i].total_mass_kg;
		r->bom_price_usd += r->bom[i].total_price_usd;
		r->bom_priced_lines += r->bom[i].unit_price_usd > 0.0;
	}
	r->bom_parts_lines = r->n_bom;
	if (m->payload_kg > 0.0)
		bom_add(r, 1, "payload", "customer-furnished", "Payload",
		    "Payload at takeoff, furnished by the customer", m->payload_kg,
		    0.0, "");
}

/* One rated element of the power path: its ratings and what one unit
 * carries (the record's flown currents, over `count` units sharing). */
static void
rate(struct res_power_rating *e, const char *what, int count,
     const struct compat_rating *r, double sized_for_a, double full_a,
     double sustained_a)
{
	memset(e, 0, sizeof *e);
	e->present = true;
	str_copy(e->what, sizeof e->what, what);
	e->count = count > 0 ? count : 1;
	e->sized_for_a = sized_for_a;
	e->full_a = full_a;
	e->sustained_a = sustained_a;
	e->continuous_a = r->continuous_a;
	e->burst_a = r->burst_a;
	e->burst_s = r->burst_s;
	e->rated_full_a = compat_rating_for(r, PERF_FULL_THROTTLE_S);
}

/* A harness run as a rated element: a conductor's chassis-wiring
 * ampacity, no burst rating. */
static void
rate_run(struct res_power_rating *e, const struct parts_run *run,
         double full_a, double sustained_a)
{
	char what[64];
	if (run->awg == NULL) {
		memset(e, 0, sizeof *e);
		return;
	}
	snprintf(what, sizeof what, "%d x %s AWG copper, %.0f mm", run->parallel,
	    run->awg, run->length_m * 1000.0);
	struct compat_rating r = { run->ampacity_a, 0.0, 0.0 };
	rate(e, what, run->n_runs, &r, run->current_a, full_a, sustained_a);
}

/* r->power_path from the record's kit and its flown currents. */
static void
fill_power_path(const struct parts_ctx *x, const struct parts_closed *c,
                struct solve_result *r)
{
	const struct parts_kit *kit = &c->kit;
	const struct res_run *o = &r->closed;
	const struct res_op *full = &o->perf.op[OP_FULL];
	struct res_power_path *pp = &r->power_path;
	memset(pp, 0, sizeof *pp);
	pp->burst_need_s = PERF_FULL_THROTTLE_S;
	double sustained = kit->load.sustained_a, q = (double)c->pack.parallel;
	double motor_sustained = o->perf.sustained_motor_current_a;
	if (kit->connector != NULL) {
		/* The plug that bounds the pack: its own family's row when the
		 * pair bought is another. */
		const struct catalog_avionics *a = kit->plug != NULL
		    && kit->plug->max_current_a > 0.0 ? kit->plug : kit->connector;
		struct compat_rating cr = { a->max_current_a, a->burst_current_a,
			a->burst_s };
		rate(&pp->connector, a->part_number, kit->n_connectors, &cr,
		    kit->load.full_a / q, o->peak_current_a / q, sustained / q);
	}
	if (kit->power_module_item) {
		struct compat_rating pr = { 0.0, 0.0, 0.0 };
		const char *what = "Power distribution (allowance, no rated catalogue part)";
		if (kit->power_module != NULL) {
			pr.continuous_a = kit->power_module->max_current_a;
			pr.burst_a = kit->power_module->burst_current_a;
			pr.burst_s = kit->power_module->burst_s;
			what = kit->power_module->part_number;
		}
		rate(&pp->power_module, what, 1, &pr, kit->load.full_a,
		    o->peak_current_a, sustained);
	}
	rate_run(&pp->harness_main, &kit->harness_main, o->peak_current_a, sustained);
	rate_run(&pp->harness_pack, &kit->harness_pack, o->peak_current_a / q,
	    sustained / q);
	rate_run(&pp->harness_arm, &kit->harness_arm, full->motor_current_a,
	    motor_sustained);
	if (c->esc != NULL) {
		struct compat_rating er = { c->esc->continuous_current_a,
			c->esc->burst_current_a, c->esc->burst_s };
		rate(&pp->esc, c->esc->part_number, x->p->n_rotors, &er,
		    kit->load.motor_full_a, full->motor_current_a, motor_sustained);
	}
}

void
parts_fill(const struct parts_ctx *x, const struct parts_closed *c,
           struct solve_result *r)
{
	fill_parts(x, c, r);
	fill_bom(x, c, r);
	fill_power_path(x, c, r);
}

/* "Maker part number" of a catalogue entry, as the reader orders it. */
#define PART_NAME(e) (e)->manufacturer, (e)->part_number

void
parts_explain(const struct parts_ctx *x, const struct parts_closed *c,
              int n_closed, int n_better_failed, struct solve_result *r)
{
	const struct catalog_motor *m = c->o.motor;
	const struct res_run *o = &r->closed;
	const struct res_op *hov = &o->perf.op[OP_HOVER];
	if (c->o.prop != NULL)
		res_rationale(r, "Motor %s %s (%.0f KV) on %s %s propellers (%.1f x %.1f in) "
		    "at %dS: J = %+.1f %% of takeoff mass over the continuous design, "
		    "the best of %d combinations of catalogue parts sized and flown; "
		    "hover at %.0f %% throttle and %.0f %% motor efficiency.",
		    PART_NAME(m), m->kv_rpm_per_v,
		    PART_NAME(c->o.prop), c->o.prop->diameter_in, c->o.prop->pitch_in,
		    c->o.cells, c->o.j, n_closed, 100.0 * hov->throttle,
		    100.0 * hov->motor_efficiency);
	else
		res_rationale(r, "Integrated system %s %s (%.0f KV, %.0f in propeller, "
		    "ESC inside) at %dS: J = %+.1f %%, the best of %d combinations "
		    "sized and flown; hover at %.0f %% throttle.", PART_NAME(m),
		    m->kv_rpm_per_v,
		    m->integrated_prop_in, c->o.cells, c->o.j, n_closed,
		    100.0 * hov->throttle);
	if (c->o.cells != x->aim.cells)
		res_rationale(r, "Bus %dS instead of the continuous %dS: the real "
		    "parts make a lighter aircraft there.", c->o.cells, x->aim.cells);
	char chem_rec[64], chem_cont[64];
	if (strcmp(c->pack.chem->name, x->p->chem->name) != 0)
		res_rationale(r, "The battery is %s (the continuous design assumed "
		    "%s): the lightest pack that flies the mission; the design of "
		    "record flies its own chemistry profile.",
		    res_chemistry_text(c->pack.chem->name, chem_rec, sizeof chem_rec),
		    res_chemistry_text(x->p->chem->name, chem_cont, sizeof chem_cont));
	res_rationale(r, "Battery: %d x %s %s (%dS%dP) = %dS %.0f mAh, %.2f kg.",
	    c->pack.series * c->pack.parallel, PART_NAME(c->pack.b), c->pack.series,
	    c->pack.parallel, c->o.cells, c->pack.capacity_ah * 1000.0,
	    c->pack.mass_kg);
	if (c->esc != NULL)
		res_rationale(r, "ESC: %d x %s %s, %.0f A continuous for the %.0f A "
		    "each motor draws at full throttle.", c->n_esc, PART_NAME(c->esc),
		    c->esc->continuous_current_a, o->perf.op[OP_FULL].motor_current_a);
	const struct parts_kit *kit = &c->kit;
	if (kit->frame != NULL)
		res_rationale(r, "Frame kit %s %s (%.0f g): %d rotors on a "
		    "%.0f mm wheelbase, the lightest catalogue kit that fits.",
		    kit->frame->manufacturer,
		    kit->frame->part_number, kit->frame->mass_kg * 1000.0,
		    kit->frame->rotor_count, kit->frame->wheelbase_m * 1000.0);
	else
		res_rationale(r, "No catalogue frame kit fits this wheelbase, "
		    "rotor count and load: the arms are CFRP tubes cut to length "
		    "(%.1f x %.2f mm, %.0f mm long).", o->arm_outer_diameter_mm,
		    o->arm_wall_thickness_mm, o->arm_length_m * 1000.0);
	double parts_g = 0.0, allow_g = 0.0;
	for (int i = 0; i < kit->n_part; i++)
		parts_g += kit->part[i]->mass_kg * 1000.0;
	for (int i = 0; i < kit->n_allowance; i++)
		allow_g += kit->allowance_kg[i] * 1000.0;
	if (kit->n_allowance > 0)
		res_rationale(r, "Avionics: %d catalogue part%s (%.0f g) and %d "
		    "allowance%s of the airframe class for what the catalogue does not "
		    "sell (%.0f g).", kit->n_part, kit->n_part == 1 ? "" : "s", parts_g,
		    kit->n_allowance, kit->n_allowance == 1 ? "" : "s", allow_g);
	else
		res_rationale(r, "Avionics: %d catalogue part%s (%.0f g).", kit->n_part,
		    kit->n_part == 1 ? "" : "s", parts_g);
	if (kit->connector != NULL)
		res_rationale(r, "Battery connectors: %d x %s %s, one per pack for "
		    "the %.0f A each pack carries at full throttle (%.0f g).",
		    kit->n_connectors, PART_NAME(kit->connector),
		    o->peak_current_a / (double)c->pack.parallel,
		    kit->connector_kg * 1000.0);
	if (o->thrust_to_weight * o->mass.total_kg
	    < x->aim.tw_required * (o->mass.total_kg + x->aim.extra_payload_kg))
		res_rationale(r, "No combination of catalogue parts reaches the required "
		    "T/W of %.2f; the design of record falls short (its thrust check "
		    "gives the verdict).", x->aim.tw_required);
	if (n_better_failed > 0)
		res_rationale(r, "%d better-scoring combination%s of catalogue parts "
		    "did not fly the mission.", n_better_failed,
		    n_better_failed == 1 ? "" : "s");
	res_rationale(r, "Design of record (the aircraft the bill of materials "
	    "builds): MTOW %.3f kg against %.3f kg continuous (%+.1f %%).",
	    o->mass.total_kg, r->custom.mass.total_kg,
	    100.0 * (o->mass.total_kg / r->custom.mass.total_kg - 1.0));
}
